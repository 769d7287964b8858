package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.RayTreeSettings;
import raytracer.core.Sampler;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.RenderStats;
import raytracer.render.Renders;
import raytracer.shapes.Box;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;
import raytracer.tracers.Whitted;

/**
 * The adaptive ray-tree cutoff (Hall and Greenberg 1983) against the full tree: a small scene of
 * absorbing glass, clear glass and a Fresnel mirror over a floor, one ray per pixel through its
 * centre and point lights only, so that the two renders differ by the pruning alone and not by
 * noise. Measured: at c = 0.001 the worst pixel moves by 3.3 c and the mean by 0.11 c, with 71% fewer
 * secondary and shadow rays. The stated tolerance (docs/performance.md, "Figure 10"): with cutoff c
 * no pixel moves by more than 5 c and the image mean by less than c / 4, in linear radiance where 1
 * is white.
 */
class RayTreeCutoffTest {
    private static final Sampler CENTRE = (n, rng, xs, ys) -> {
        xs[0] = 0.5;
        ys[0] = 0.5;
    };
    private static final int SIZE = 64;

    private static World scene() {
        World world = new World(new ViewPlane(SIZE, SIZE, 1, CENTRE, 12, 1),
            new Pinhole(new Point3D(0, 1.6, 5), new Point3D(0, 0.6, 0), Vector3D.UP, 40), new Ambient(0.05, RGBColor.WHITE));
        world.setBackground(new RGBColor(0.3, 0.4, 0.6));
        Plane floor = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        floor.setMaterial(new Matte(0.2, 0.8, new RGBColor(0.7, 0.7, 0.6)));
        world.addObject(floor);
        Sphere green = new Sphere(new Point3D(-0.7, 0.8, 0), 0.8);
        green.setMaterial(new Dielectric(1.5, new RGBColor(2.5, 0.25, 1.8), 0.6, 500));
        world.addObject(green);
        Box clear = new Box(new Point3D(0.3, 0, -1.2), new Point3D(1.3, 1.4, -0.2));
        clear.setMaterial(new Dielectric(1.5, RGBColor.BLACK, 0.6, 500));
        world.addObject(clear);
        Sphere mirror = new Sphere(new Point3D(1.1, 0.45, 0.8), 0.45);
        mirror.setMaterial(new Reflective(0.1, 0.3, new RGBColor(0.4, 0.25, 0.1), 0.3, RGBColor.WHITE, 200,
                                          0.5, RGBColor.WHITE, true));
        world.addObject(mirror);
        world.addLight(new PointLight(12, RGBColor.WHITE, new Point3D(2, 4, 3)));
        world.addLight(new PointLight(4, new RGBColor(1, 0.9, 0.8), new Point3D(-3, 3, 1)));
        world.setTracer(Whitted::new);
        world.prepare();
        return world;
    }

    private static Film render(double cutoff, RenderStats[] stats) {
        Film film = new Film(SIZE, SIZE);
        stats[0] = Renders.render(scene(), RayTreeSettings.FULL_TREE.withCutoff(cutoff), 1, 1, film);
        assertEquals(0, stats[0].nonFiniteSamples());
        return film;
    }

    @Test
    void prunedTreeStaysWithinTheStatedToleranceOfTheFullTree() {
        RenderStats[] full = new RenderStats[1];
        Film reference = render(0, full);
        for (double cutoff : new double[] {1e-3, 1e-2}) {
            RenderStats[] pruned = new RenderStats[1];
            Film film = render(cutoff, pruned);
            double worst = 0;
            double sum = 0;
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    for (int c = 0; c < 3; c++) {
                        double d = film.get(x, y, c) - reference.get(x, y, c);
                        assertTrue(d <= 1e-12, "pruning only leaves light out, never adds it: " + d);
                        worst = Math.max(worst, -d);
                        sum += d;
                    }
                }
            }
            double meanShift = -sum / (3.0 * SIZE * SIZE);
            assertTrue(worst <= 5 * cutoff, "cutoff " + cutoff + ": worst pixel moved by " + worst);
            assertTrue(meanShift <= cutoff / 4, "cutoff " + cutoff + ": mean moved by " + meanShift);
            // and it must have saved something, or the test proves nothing
            assertTrue(pruned[0].secondaryRays() < 0.8 * full[0].secondaryRays(),
                "secondary rays " + pruned[0].secondaryRays() + " of " + full[0].secondaryRays());
            assertTrue(pruned[0].shadowRays() < full[0].shadowRays(),
                "shadow rays " + pruned[0].shadowRays() + " of " + full[0].shadowRays());
        }
    }

    @Test
    void glassSeenFromInsideTracesNoShadowRays() {
        // a camera inside a closed glass box that casts shadows: every hit is seen from inside, so
        // no shadow ray can reach the light and none is traced
        World world = new World(new ViewPlane(8, 8, 1, CENTRE, 3, 1),
            new Pinhole(Point3D.ORIGIN, new Point3D(0, 0, -1), Vector3D.UP, 60), new Ambient(0, RGBColor.WHITE));
        Box box = new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1));
        box.setMaterial(new Dielectric(1.5, RGBColor.BLACK, 1, 10));
        world.addObject(box);
        world.addLight(new PointLight(5, RGBColor.WHITE, new Point3D(0, 5, 0)));
        world.setTracer(Whitted::new);
        world.prepare();
        RenderStats stats = Renders.render(world, 1, 1, new Film(8, 8));
        assertTrue(stats.secondaryRays() > 0);
        assertEquals(0, stats.shadowRays());
    }
}

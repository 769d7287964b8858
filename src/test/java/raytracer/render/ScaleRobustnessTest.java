package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cameras.Pinhole;
import raytracer.core.GeometricObject;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.materials.Matte;
import raytracer.materials.Reflective;
import raytracer.math.Matrix4;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.shapes.Box;
import raytracer.shapes.Instance;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;
import raytracer.tracers.Whitted;

/**
 * The same scene built at scales from 1e-4 to 1e6 units, placed far from the origin as well, must
 * give the same image as at scale 1: shadow acne (self-shadowed speckles) or light leaking through
 * touching objects would show up as pixels that differ. Light intensity scales with s^2 so that
 * radiance, I / r^2, is scale-free.
 */
class ScaleRobustnessTest {
    private static final int W = 96;
    private static final int H = 64;

    @ParameterizedTest
    @ValueSource(doubles = {1e-4, 1e-2, 1e2, 1e4, 1e6})
    void imageDoesNotDependOnTheSceneScale(double scale) {
        Film reference = render(1, 0);
        Film scaled = render(scale, 0);
        Film shifted = render(scale, 1000 * scale);
        assertSimilar(reference, scaled, "scale " + scale);
        assertSimilar(reference, shifted, "scale " + scale + " moved away from the origin");
    }

    private static void assertSimilar(Film a, Film b, String what) {
        int differing = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    float va = a.get(x, y, c);
                    float vb = b.get(x, y, c);
                    assertTrue(Float.isFinite(vb), what + ": non-finite pixel");
                    if (Math.abs(va - vb) > 1e-3 * Math.max(1, va)) {
                        differing++;
                    }
                }
            }
        }
        // silhouette pixels may flip under rounding; acne would affect whole lit regions
        assertTrue(differing <= 3, what + ": " + differing + " channels differ from the scale-1 image");
    }

    private static Film render(double s, double offset) {
        ViewPlane vp = new ViewPlane(W, H, 1, CenterSampler.INSTANCE, 3, 1);
        Point3D eye = new Point3D(offset + 0, s * 2.5, offset + s * 7);
        World world = new World(vp, new Pinhole(eye, new Point3D(offset, s * 0.8, offset), Vector3D.UP, 50),
                                new Ambient(0.05, RGBColor.WHITE));
        Matte matte = new Matte(0.2, 0.8, new RGBColor(0.8, 0.7, 0.6));
        add(world, new Plane(new Point3D(offset, 0, offset), new Normal(0, 1, 0)), matte);
        // a sphere resting on the plane, touching it: no light may leak under it
        add(world, new Sphere(new Point3D(offset - s * 1.2, s, offset), s), matte);
        // a box standing on the plane, rotated, so its faces are hit at slanted angles
        GeometricObject box = new Instance(new Box(new Point3D(-s * 0.6, 0, -s * 0.6), new Point3D(s * 0.6, s * 1.2, s * 0.6)),
            Matrix4.translate(offset + s * 1.3, 0, offset).multiply(Matrix4.rotateY(35)));
        add(world, box, matte);
        add(world, new Sphere(new Point3D(offset, s * 0.5, offset + s * 1.6), s * 0.5),
            new Reflective(0.1, 0.2, RGBColor.WHITE, 0.2, RGBColor.WHITE, 50, 0.7, RGBColor.WHITE, false));
        world.addLight(new PointLight(40 * s * s, RGBColor.WHITE, new Point3D(offset - s * 3, s * 5, offset + s * 4)));
        world.setTracer(Whitted::new);
        world.prepare();
        Film film = new Film(W, H);
        RenderStats stats = Renders.render(world, 2, 1, film);
        assertEquals(0, stats.nonFiniteSamples());
        return film;
    }

    private static void add(World world, GeometricObject object, raytracer.core.Material material) {
        object.setMaterial(material);
        world.addObject(object);
    }
}

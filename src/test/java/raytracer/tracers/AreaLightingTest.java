package raytracer.tracers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.brdf.FittedPreset;
import raytracer.cameras.Pinhole;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.AreaLight;
import raytracer.lights.Directional;
import raytracer.lights.PointLight;
import raytracer.materials.Dielectric;
import raytracer.materials.Fitted;
import raytracer.materials.GlossyReflector;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.materials.Reflective;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.Vector3D;
import raytracer.render.RenderStats;
import raytracer.render.Renders;
import raytracer.samplers.MultiJittered;
import raytracer.shapes.Box;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;

/**
 * The two shading forms agree where both apply: for lights without extent (G = pdf = 1, one
 * sample, no pattern drawn) areaLightShade is shade, so the AreaLighting tracer gives Whitted's
 * image bit for bit, with every material, random glossy rays, the passes and the cutoff. And a
 * tracer that calls shade refuses an area light instead of rendering it wrongly.
 */
class AreaLightingTest {
    private static final int SIZE = 40;

    private static World scene(Function<World, Tracer> tracer) {
        World world = new World(new ViewPlane(SIZE, SIZE, 4, new MultiJittered(), 6, 1),
            new Pinhole(new Point3D(0, 1.6, 5), new Point3D(0, 0.6, 0), Vector3D.UP, 50), new Ambient(0.1, RGBColor.WHITE));
        world.setBackground(new RGBColor(0.3, 0.4, 0.6));
        Plane floor = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        floor.setMaterial(new Matte(0.2, 0.8, new RGBColor(0.7, 0.7, 0.6)));
        world.addObject(floor);
        Sphere glass = new Sphere(new Point3D(-1.2, 0.6, 0), 0.6);
        glass.setMaterial(new Dielectric(1.5, new RGBColor(0.5, 0.1, 0.3), 0.5, 200));
        world.addObject(glass);
        Sphere glossy = new Sphere(new Point3D(0.2, 0.5, -0.6), 0.5);
        glossy.setMaterial(new GlossyReflector(0.1, 0.4, new RGBColor(0.8, 0.5, 0.3), 0.6, RGBColor.WHITE, 50, 4, true));
        world.addObject(glossy);
        Sphere mirror = new Sphere(new Point3D(1.3, 0.45, 0.4), 0.45);
        mirror.setMaterial(new Reflective(0.1, 0.3, new RGBColor(0.4, 0.25, 0.1), 0.3, RGBColor.WHITE, 100, 0.5, RGBColor.WHITE, true));
        world.addObject(mirror);
        Box phong = new Box(new Point3D(-0.4, 0, 0.6), new Point3D(0.2, 0.4, 1.2));
        phong.setMaterial(new Phong(0.2, 0.6, new RGBColor(0.2, 0.6, 0.3), 0.4, RGBColor.WHITE, 30, false));
        world.addObject(phong);
        Sphere fitted = new Sphere(new Point3D(0.9, 0.3, 1.4), 0.3);
        fitted.setMaterial(Fitted.of(FittedPreset.DELRIN_WARD, 1, false));
        world.addObject(fitted);
        Sphere seed = new Sphere(new Point3D(-0.9, 0.25, 1.5), 0.25);
        seed.setMaterial(Fitted.of(FittedPreset.NICKEL_BLINN_PHONG, 1, true));
        world.addObject(seed);
        world.addLight(new PointLight(12, RGBColor.WHITE, new Point3D(2, 4, 3)));
        world.addLight(new Directional(1, new RGBColor(1, 0.9, 0.8), new Vector3D(-1, 2, 1)));
        world.setTracer(tracer);
        world.prepare();
        return world;
    }

    private static Film render(World world, double cutoff, ShadingPass pass, RenderStats[] stats) {
        Film film = new Film(SIZE, SIZE);
        stats[0] = Renders.render(world, new RayTreeSettings(pass, cutoff), 2, 5, film);
        return film;
    }

    @ParameterizedTest
    @CsvSource({"0, FULL", "0.001, FULL", "0.01, FULL", "0, DIRECT", "0, MAGENTA_REFLECTION", "0, NO_FRESNEL"})
    void withoutAreaLightsAreaLightingIsWhittedBitForBit(double cutoff, ShadingPass pass) {
        RenderStats[] whittedStats = new RenderStats[1];
        RenderStats[] areaStats = new RenderStats[1];
        Film whitted = render(scene(Whitted::new), cutoff, pass, whittedStats);
        Film area = render(scene(AreaLighting::new), cutoff, pass, areaStats);
        double sum = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(whitted.get(x, y, c), area.get(x, y, c), 0, "pixel " + x + "," + y + " channel " + c);
                    sum += whitted.get(x, y, c);
                }
            }
        }
        assertTrue(sum > 0.05 * SIZE * SIZE, "the scene is lit: " + sum);
        assertEquals(whittedStats[0].shadowRays(), areaStats[0].shadowRays());
        assertEquals(whittedStats[0].secondaryRays(), areaStats[0].secondaryRays());
        assertTrue(areaStats[0].secondaryRays() > 0 || pass == ShadingPass.DIRECT, "mirrors, glass and glossy rays traced");
    }

    @Test
    void tracersThatShadeFromOneDirectionRefuseAreaLights() {
        World world = new World(new ViewPlane(4, 4, 1, new MultiJittered(), 2, 1),
            new Pinhole(new Point3D(0, 2, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 40), new Ambient(0, RGBColor.WHITE));
        Plane floor = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        floor.setMaterial(new Matte(0, 1, RGBColor.WHITE));
        world.addObject(floor);
        world.addLight(AreaLight.disk(new Point3D(0, 1, 0), new Vector3D(0, -1, 0), 0.5, 1, RGBColor.WHITE, 4));
        world.prepare();
        WorkerScratch scratch = new WorkerScratch(world);
        Ray down = new Ray().set(0, 2, 0, 0, -1, 0);
        MutableRgb out = new MutableRgb();
        for (Tracer tracer : new Tracer[] {new Whitted(world), new RayCast(world)}) {
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> tracer.traceRay(down, 0, scratch, out));
            assertTrue(e.getMessage().contains("AreaLighting"), e.getMessage());
        }
        new AreaLighting(world).traceRay(down, 0, scratch, out);
        assertTrue(out.r > 0, "AreaLighting samples it: " + out.r);
    }
}

package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.GeometricObject;
import raytracer.core.RayTreeSettings;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.materials.GlossyReflector;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.Samplers;
import raytracer.shapes.Instance;
import raytracer.shapes.Sphere;
import raytracer.tracers.Whitted;

/** The renderer's limits and its pool: the deepest recursion a worker can hold, renders repeated on one pool. */
class RendererTest {
    @Test
    void rendersRepeatedOnOnePoolGiveTheSameImage() {
        // --repeat renders on the run's one pool: a renderer that shut the pool down after its
        // render would fail the second time
        World world = insideAMirror(3);
        Film[] films = {new Film(4, 4), new Film(4, 4)};
        RenderStats[] stats = new RenderStats[2];
        try (Workers workers = new Workers(2)) {
            for (int i = 0; i < 2; i++) {
                stats[i] = new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1).render(films[i]);
            }
        }
        for (int i = 0; i < 2; i++) {
            assertEquals(2, stats[i].threads());
            assertEquals(16L * 3, stats[i].secondaryRays(), "each render counts its own rays, render " + i);
        }
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 4; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(films[0].get(x, y, c), films[1].get(x, y, c), 0, "pixel " + x + ", " + y);
                }
            }
        }
    }

    @Test
    void theDeepestRecursionAllowedFitsAWorkersStack() {
        // a camera inside a mirror sphere, one glossy ray per hit through an instance: every ray
        // recurses to the full depth (max-depth 100000 ran out of memory, 3000 out of stack)
        World world = insideAMirror(ViewPlane.MAX_DEPTH);
        Film film = new Film(4, 4);
        RenderStats stats = Renders.render(world, 2, 1, film);
        assertEquals(16L * ViewPlane.MAX_DEPTH, stats.secondaryRays(), "every level was traced");
        assertTrue(film.get(1, 1, 0) > 0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> world.viewPlane().withMaxDepth(ViewPlane.MAX_DEPTH + 1));
        assertEquals("max depth must be 0 to 1000, got 1001", e.getMessage());
    }

    private static World insideAMirror(int depth) {
        // random samples: the glossy rays wander about the mirror direction; a fixed pattern would drift them to grazing
        ViewPlane vp = new ViewPlane(4, 4, 1, Samplers.byName("random"), depth, 1);
        World world = new World(vp, new Pinhole(Point3D.ORIGIN, new Point3D(0, 0, -1), Vector3D.UP, 45),
                                new Ambient(0, RGBColor.WHITE));
        GeometricObject mirror = new Instance(new Sphere(Point3D.ORIGIN, 2), Matrix4.rotateX(10));
        mirror.setMaterial(new GlossyReflector(0, 0.2, RGBColor.WHITE, 0.8, RGBColor.WHITE, 100_000, 1, false));
        world.addObject(mirror);
        world.addLight(new PointLight(1, RGBColor.WHITE, new Point3D(0, 0.5, 0)));
        world.setTracer(Whitted::new);
        world.prepare();
        return world;
    }
}

package raytracer.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.core.RayTreeSettings;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneLoader;
import raytracer.math.MutableRgb;
import raytracer.math.Ray;
import raytracer.render.RenderStats;
import raytracer.render.Workers;

/**
 * The allocation study compares like with like: a scene with a sphere, a plane, a smooth mesh and a
 * box (both under transforms), matte, Phong and mirror materials, two point lights and a
 * directional one with shadows, and mirrors facing each other, rendered in every mode, gives the
 * same image to the bit and traces the same rays. The modes do the same operations in the same
 * order (the immutable path's records compute each component as the renderer's mutable code
 * does), so no tolerance is needed: any difference is a step done differently.
 */
class AllocationModeTest {
    private static final String SCENE = """
        image: {width: 40, height: 30, samples: 4, sampler: multi-jittered, max-depth: 5}
        tracer: TRACER
        background: [0.5, 0.6, 0.8]
        camera: {type: pinhole, eye: [0.5, 2, 7], look-at: [0, 0.8, 0], fov: 50}
        ambient: {radiance: 0.3, color: [0.6, 0.7, 0.9]}
        materials:
          floor:  {type: phong, ka: 0.2, kd: 0.7, color: [0.8, 0.75, 0.7], ks: 0.1, exponent: 15}
          clay:   {type: matte, ka: 0.25, kd: 0.8, color: [0.9, 0.4, 0.3]}
          jade:   {type: phong, ka: 0.2, kd: 0.7, color: [0.3, 0.7, 0.5], ks: 0.4, exponent: 50, normalized: true}
          mirror: {type: reflective, ka: 0, kd: 0.05, color: [1, 1, 1], ks: 0.5, exponent: 300, kr: 0.9, reflect-color: [0.95, 0.97, 1]}
        lights:
          - {type: point, position: [-4, 6, 5], intensity: 90, color: [1, 0.9, 0.8]}
          - {type: point, position: [3, 3, 3], intensity: 20, shadows: false}
          - {type: directional, direction: [2, 5, 1], radiance: 1.2, color: [0.8, 0.9, 1]}
        objects:
          - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor}
          - {type: sphere, center: [0, 1, 0], radius: 1, material: mirror}
          - {type: sphere, center: [-2, 0.6, 1], radius: 0.6, material: clay}
          - {type: sphere, center: [0.5, 1.5, 12], radius: 3, material: mirror}
          - {type: mesh, file: octahedron.obj, smooth: true, material: jade, transform: [{scale: 0.8}, {translate: [1.9, 0.8, 0.6]}]}
          - {type: box, min: [-0.5, 0, -0.5], max: [0.5, 1, 0.5], material: clay, transform: [{rotate-y: 30}, {translate: [-1.5, 0, -2]}]}
        """;

    private static final String OCTAHEDRON = """
        v 1 0 0
        v -1 0 0
        v 0 1 0
        v 0 -1 0
        v 0 0 1
        v 0 0 -1
        f 1 3 5
        f 3 2 5
        f 2 4 5
        f 4 1 5
        f 3 1 6
        f 2 3 6
        f 4 2 6
        f 1 4 6
        """;

    @TempDir
    Path folder;

    /** The scene named, loaded afresh (each mode changes its world) and prepared. */
    private LoadedScene load(String scene) throws Exception {
        if (scene.equals("default")) {
            try (InputStream in = AllocationModeTest.class.getResourceAsStream("/raytracer/scenes/default.yaml")) {
                LoadedScene loaded = SceneLoader.load("default scene", new String(in.readAllBytes(), StandardCharsets.UTF_8));
                // a small image of the default scene, as its file says it, with fewer samples
                ViewPlane vp = loaded.world().viewPlane();
                loaded.world().setViewPlane(new ViewPlane(48, 27, 4, vp.sampler(), vp.maxDepth(), vp.exposure()));
                loaded.world().prepare();
                return loaded;
            }
        }
        Files.writeString(folder.resolve("octahedron.obj"), OCTAHEDRON);
        Path file = folder.resolve(scene + ".yaml");
        Files.writeString(file, SCENE.replace("TRACER", scene));
        LoadedScene loaded = SceneLoader.load(file);
        loaded.world().prepare();
        return loaded;
    }

    @ParameterizedTest
    @ValueSource(strings = {"whitted", "ray-cast", "default"})
    void everyModeRendersTheSameImageAndTracesTheSameRays(String scene) throws Exception {
        Film[] films = new Film[AllocationMode.values().length];
        RenderStats[] stats = new RenderStats[films.length];
        for (AllocationMode mode : AllocationMode.values()) {
            LoadedScene loaded = load(scene);
            World world = loaded.world();
            Tracer loadedTracer = world.tracer();
            mode.install(world, loaded.rayTree());
            if (mode == AllocationMode.IMMUTABLE) {
                assertInstanceOf(ImmutableWhitted.class, world.tracer(), "the immutable mode traces with the study's own tracer");
            } else {
                assertSame(loadedTracer, world.tracer());
            }
            films[mode.ordinal()] = new Film(world.viewPlane().hres(), world.viewPlane().vres());
            try (Workers workers = new Workers(2)) {
                stats[mode.ordinal()] = mode.renderer(world, loaded.rayTree(), workers, 7).render(films[mode.ordinal()]);
            }
        }
        RenderStats reuse = stats[0];
        assertTrue(reuse.shadowRays() > reuse.primaryRays(), "lights are tested for shadows: " + reuse);
        if (!scene.equals("ray-cast")) {
            assertTrue(reuse.secondaryRays() > reuse.primaryRays() / 50, "mirrors reflect: " + reuse);
        }
        for (int m = 1; m < films.length; m++) {
            String mode = AllocationMode.values()[m].key();
            assertEquals(reuse.primaryRays(), stats[m].primaryRays(), mode);
            assertEquals(reuse.secondaryRays(), stats[m].secondaryRays(), mode);
            assertEquals(reuse.shadowRays(), stats[m].shadowRays(), mode);
            assertEquals(0, stats[m].nonFiniteSamples(), mode);
            Film film = films[m];
            for (int y = 0; y < film.height(); y++) {
                for (int x = 0; x < film.width(); x++) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(Float.floatToIntBits(films[0].get(x, y, c)), Float.floatToIntBits(film.get(x, y, c)),
                                     mode + " against reuse at pixel " + x + ", " + y + ", channel " + c);
                    }
                }
            }
        }
    }

    /** Before the pixel's average rounds to float: the radiance of every camera ray, as doubles, to the bit. */
    @Test
    void everyModeGivesEachRayTheSameRadianceToTheBit() throws Exception {
        int width = 40;
        int height = 30;
        double[][] radiance = new double[AllocationMode.values().length][3 * width * height * 4];
        for (AllocationMode mode : AllocationMode.values()) {
            LoadedScene loaded = load("whitted");
            World world = loaded.world();
            mode.install(world, loaded.rayTree());
            WorkerScratch scratch = mode.scratch(world, loaded.rayTree());
            Ray ray = new Ray();
            MutableRgb out = new MutableRgb();
            int k = 0;
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    for (int s = 0; s < 4; s++) {
                        world.camera().generateRay(world.viewPlane(), x + 0.25 + 0.5 * (s & 1), y + 0.25 + 0.5 * (s >> 1), 0, 0, ray);
                        world.tracer().traceRay(ray, 0, scratch, out);
                        radiance[mode.ordinal()][k++] = out.r;
                        radiance[mode.ordinal()][k++] = out.g;
                        radiance[mode.ordinal()][k++] = out.b;
                    }
                }
            }
        }
        for (int m = 1; m < radiance.length; m++) {
            for (int k = 0; k < radiance[0].length; k++) {
                assertEquals(Double.doubleToLongBits(radiance[0][k]), Double.doubleToLongBits(radiance[m][k]),
                             AllocationMode.values()[m].key() + " against reuse: " + radiance[m][k] + " for " + radiance[0][k]
                             + " at value " + k);
            }
        }
    }

    @Test
    void aFreshSupplyGivesANewRecordForEveryRayAndReuseTheSameOne() throws Exception {
        LoadedScene loaded = load("whitted");
        WorkerScratch reuse = AllocationMode.REUSE.scratch(loaded.world(), loaded.rayTree());
        assertSame(reuse.shadeRec(1), reuse.shadeRec(1));
        assertNotSame(reuse.shadeRec(1), reuse.shadeRec(2));
        for (AllocationMode mode : new AllocationMode[] {AllocationMode.FRESH, AllocationMode.IMMUTABLE}) {
            WorkerScratch fresh = mode.scratch(loaded.world(), loaded.rayTree());
            assertNotSame(fresh.shadeRec(1), fresh.shadeRec(1), mode.key());
            assertSame(fresh, fresh.shadeRec(0).scratch, mode.key());
        }
    }

    @Test
    void theImmutablePathRefusesWhatItDoesNotHave() throws Exception {
        // what to replace, by what, the tracer, and what the message names
        String[][] cases = {
            {"clay:   {type: matte, ka: 0.25, kd: 0.8, color: [0.9, 0.4, 0.3]}",
             "clay:   {type: dielectric, ior: 1.5}", "whitted", "material Dielectric"},
            {"kr: 0.9,", "kr: 0.9, fresnel: schlick,", "whitted", "reflective material with Schlick's Fresnel"},
            {"clay:   {type: matte, ka: 0.25, kd: 0.8, color: [0.9, 0.4, 0.3]}",
             "clay:   {type: matte, ka: 0.25, kd: 0.8, texture: {type: checker, size: 1}}", "whitted", "textured material"},
            {"- {type: directional, direction: [2, 5, 1], radiance: 1.2, color: [0.8, 0.9, 1]}",
             "- {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], radiance: 2}",
             "area-lighting", "tracer AreaLighting"},
        };
        Files.writeString(folder.resolve("octahedron.obj"), OCTAHEDRON);
        for (String[] c : cases) {
            assertTrue(SCENE.contains(c[0]), c[0]);
            Path file = folder.resolve("refused.yaml");
            Files.writeString(file, SCENE.replace("TRACER", c[2]).replace(c[0], c[1]));
            LoadedScene loaded = SceneLoader.load(file);
            loaded.world().prepare();
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> AllocationMode.IMMUTABLE.install(loaded.world(), loaded.rayTree()), c[3]);
            assertTrue(e.getMessage().startsWith("the allocation study's immutable path has no " + c[3] + "; it has "),
                       e.getMessage());
        }
        LoadedScene loaded = load("whitted");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> AllocationMode.IMMUTABLE.install(loaded.world(), RayTreeSettings.FULL_TREE.withCutoff(0.01)));
        assertTrue(e.getMessage().startsWith("the allocation study's immutable path has no pass 'full' with cutoff 0.01;"),
                   e.getMessage());
        assertEquals(AllocationMode.FRESH, AllocationMode.parse("fresh"));
        assertThrows(IllegalArgumentException.class, () -> AllocationMode.parse("pooled"));
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.brdf.FittedPreset;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.filters.Gaussian;
import raytracer.image.DisplayEncoding;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.shapes.Instance;
import raytracer.tracers.RayCast;

class SceneLoaderTest {
    private static final String BASE = """
        image: {width: 32, height: 16, samples: 3, sampler: jittered, max-depth: 2, exposure: 2}
        materials:
          red: {type: phong, color: [1, 0, 0]}
        lights:
          - {type: point, position: [0, 5, 0], intensity: 10}
        objects:
          - {type: sphere, center: [0, 0, 0], radius: 1, material: red}
        """;

    private static String error(String text) {
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load("s.yaml", text));
        assertEquals(1, e.getMessage().lines().count(), "one line: " + e.getMessage());
        return e.getMessage();
    }

    private static void assertMessage(String message, String prefix, String... fragments) {
        assertTrue(message.startsWith(prefix), "expected '" + prefix + "' at the start of: " + message);
        for (String f : fragments) {
            assertTrue(message.contains(f), "'" + f + "' missing from: " + message);
        }
    }

    /** The radiance the scene's tracer brings back along a ray from (ox, oy, oz) in direction d. */
    private static MutableRgb trace(World world, double ox, double oy, double oz, double dx, double dy, double dz) {
        world.prepare();
        MutableRgb out = new MutableRgb();
        world.tracer().traceRay(new Ray().set(ox, oy, oz, dx, dy, dz), 0, new WorkerScratch(world), out);
        return out;
    }

    @Test
    void theFileGivesTheRayTreeSettingsAndTheEncodingBesideTheWorld() throws SceneException {
        LoadedScene plain = SceneLoader.load("s.yaml", BASE);
        assertEquals(RayTreeSettings.FULL_TREE, plain.rayTree(), "no pass, no cutoff: the whole tree");
        assertEquals(DisplayEncoding.SRGB, plain.encoding());
        LoadedScene set = SceneLoader.load("s.yaml", "pass: magenta-reflection\n"
                                           + BASE.replace("image: {", "image: {cutoff: 0.02, encoding: linear, "));
        assertEquals(new RayTreeSettings(ShadingPass.MAGENTA_REFLECTION, 0.02), set.rayTree());
        assertEquals(DisplayEncoding.LINEAR, set.encoding());
        assertEquals(2, set.world().viewPlane().exposure(), "the rest of image: still reaches the view plane");
    }

    private static void assertRgb(double r, double g, double b, MutableRgb actual, String what) {
        assertEquals(r, actual.r, 1e-9 * Math.max(1, r), what + ", red");
        assertEquals(g, actual.g, 1e-9 * Math.max(1, g), what + ", green");
        assertEquals(b, actual.b, 1e-9 * Math.max(1, b), what + ", blue");
    }

    @Test
    void validSceneLoadsWithItsSettings() throws SceneException {
        World world = SceneLoader.load("s.yaml", BASE + "  - {type: plane, normal: [0, 1, 0]}\n"
            + "  - {type: box, min: [0, 0, 0], max: [1, 1, 1], transform: [{rotate-y: 30}, {translate: [1, 0, 0]}]}\n").world();
        assertEquals(32, world.viewPlane().hres());
        assertEquals(16, world.viewPlane().vres());
        assertEquals(4, world.viewPlane().numSamples(), "jittered rounds 3 up to 4");
        assertEquals(2, world.viewPlane().maxDepth());
        assertEquals(2, world.viewPlane().exposure());
        assertEquals(3, world.objects().size());
        assertTrue(world.objects().get(2) instanceof Instance);
        world.prepare();
        assertEquals(1, world.lights().length);
    }

    @Test
    void theImageMayAskForTheGaussianFilter() throws SceneException {
        assertEquals(PixelFilter.BOX, SceneLoader.load("s.yaml", BASE).world().viewPlane().filter(), "the book's box by default");
        Gaussian standard = (Gaussian) SceneLoader.load("s.yaml", BASE.replace("image: {", "image: {filter: gaussian, "))
            .world().viewPlane().filter();
        assertEquals("gaussian", standard.name());
        assertEquals(0.5, standard.stddev());
        Gaussian wide = (Gaussian) SceneLoader.load("s.yaml", BASE.replace("image: {", "image: {filter: gaussian, filter-stddev: 1, "))
            .world().viewPlane().filter();
        assertEquals(1, wide.stddev());
        assertEquals(4, wide.radius());
    }

    @Test
    void defaultsApplyToAMinimalScene() throws SceneException {
        World world = SceneLoader.load("min.yaml", "tracer: ray-cast\nobjects:\n  - {type: sphere, center: [0, 0, 0]}\n").world();
        assertEquals(640, world.viewPlane().hres());
        assertEquals(360, world.viewPlane().vres());
        assertEquals(4, world.viewPlane().numSamples());
        assertTrue(world.tracer() instanceof RayCast);
        assertTrue(world.objects().get(0).getMaterial() != null, "a default material");
    }

    /** The tracer follows the lights unless the scene names one; whitted and ray-cast cannot take area lights. */
    @Test
    void scenesWithAreaLightsGetTheAreaLightingTracer() throws SceneException {
        assertTrue(SceneLoader.load("s.yaml", BASE).world().tracer() instanceof raytracer.tracers.Whitted);
        String area = BASE.replace("{type: point, position: [0, 5, 0], intensity: 10}",
                                   "{type: disk, center: [0, 5, 0], normal: [0, -1, 0]}");
        assertTrue(SceneLoader.load("s.yaml", area).world().tracer() instanceof raytracer.tracers.AreaLighting);
        assertTrue(SceneLoader.load("s.yaml", "tracer: area-lighting\n" + area).world().tracer() instanceof raytracer.tracers.AreaLighting);
        assertTrue(SceneLoader.load("s.yaml", "tracer: area-lighting\n" + BASE).world().tracer() instanceof raytracer.tracers.AreaLighting,
                   "point lights alone may be sampled too");
        assertMessage(error("tracer: whitted\n" + area), "s.yaml:1:9:", "'whitted' cannot sample", "area-lighting");
        assertMessage(error("tracer: ray-cast\n" + area), "s.yaml:1:9:", "'ray-cast' cannot sample", "max-depth: 0");
    }

    @Test
    void jsonIsAccepted() throws SceneException {
        World world = SceneLoader.load("s.json", "{\"image\": {\"width\": 8, \"height\": 8}, \"objects\": "
                                                 + "[{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 2}]}").world();
        assertEquals(8, world.viewPlane().hres());
    }

    @Test
    void theDocumentedExampleLoads() throws IOException, SceneException {
        String doc = Files.readString(Path.of("docs/scene-format.md"));
        int start = doc.indexOf("```yaml\n") + 8;
        String example = doc.substring(start, doc.indexOf("```", start));
        World world = SceneLoader.load("docs/scene-format.md", example).world();
        assertEquals(6, world.objects().size());
        assertEquals(800, world.viewPlane().hres());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        unknown key in an object     | - {type: sphere, center: [0, 0, 0], radus: 1}                   | s.yaml:8:39: | unknown key 'radus' in sphere; allowed: casts-shadows, center, material, radius, transform, type
        unknown object type          | - {type: teapot}                                                 | s.yaml:8:12: | teapot'; allowed: box, cylinder, mesh, plane, sphere
        negative radius              | - {type: sphere, center: [0, 0, 0], radius: -1}                  | s.yaml:8:47: | 'radius' in sphere must be greater than 0, got -1
        zero radius                  | - {type: sphere, center: [0, 0, 0], radius: 0}                   | s.yaml:8:47: | greater than 0
        NaN coordinate               | - {type: sphere, center: [0, .nan, 0]}                           | s.yaml:8:32: | must be a finite number, got '.nan'
        infinite coordinate          | - {type: sphere, center: [0, 0, .inf]}                           | s.yaml:8:35: | must be a finite number, got '.inf'
        text where a number is due   | - {type: sphere, center: [0, 0, 0], radius: big}                 | s.yaml:8:47: | must be a number, got 'big'
        two numbers for a point      | - {type: sphere, center: [0, 0]}                                 | s.yaml:8:28: | 3 numbers [x, y, z], got a list of 2
        undefined material           | - {type: sphere, center: [0, 0, 0], material: gold}              | s.yaml:8:49: | material 'gold' is not defined; defined: red
        duplicate key                | - {type: sphere, center: [0, 0, 0], center: [1, 1, 1]}           | s.yaml:8:                | duplicate
        missing required key         | - {type: box, min: [0, 0, 0]}                                    | s.yaml:8:5:  | box needs the key 'max'
        flat box                     | - {type: box, min: [0, 0, 0], max: [1, 0, 1]}                    | s.yaml:8:5:  | positive size
        singular transform           | - {type: sphere, center: [0, 0, 0], transform: [{scale: 0}]}     | s.yaml:8:50: | singular
        non-affine matrix            | - {type: sphere, center: [0, 0, 0], transform: [{matrix: [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1]}]} | s.yaml:8:60: | affine
        degenerate triangle count    | - {type: triangle, vertices: [[0, 0, 0], [1, 0, 0]]}             | s.yaml:8:32: | 3 points, got 2
        """)
    void badObjectsNameLineColumnAndKey(String what, String object, String prefix, String fragment) {
        String message = error(BASE + "  " + object + "\n");
        assertMessage(message, prefix.strip(), fragment.strip());
    }

    @Test
    void imageValuesAreRangeChecked() {
        assertMessage(error(BASE.replace("width: 32", "width: 0")), "s.yaml:1:16:", "'width' in image must be at least 1, got 0");
        assertMessage(error(BASE.replace("height: 16", "height: -4")), "s.yaml:1:28:", "at least 1");
        assertMessage(error(BASE.replace("samples: 3", "samples: 0")), "s.yaml:1:41:", "'samples'");
        assertMessage(error(BASE.replace("samples: 3", "samples: 2.5")), "s.yaml:1:41:", "whole number");
        assertMessage(error(BASE.replace("max-depth: 2", "max-depth: -1")), "s.yaml:1:", "'max-depth'");
        // each level of recursion holds a hit record per worker and stack frames: 100000 ran out of memory
        assertMessage(error(BASE.replace("max-depth: 2", "max-depth: 100000")), "s.yaml:1:74:",
                      "'max-depth' in image must be at most 1000, got 100000");
        assertMessage(error(BASE.replace("exposure: 2", "exposure: 0")), "s.yaml:1:", "'exposure'", "greater than 0");
        assertMessage(error(BASE.replace("sampler: jittered", "sampler: poisson-disk")), "s.yaml:1:", "poisson-disk", "multi-jittered");
        assertMessage(error(BASE.replace("image: {", "image: {colour: 1, ")), "s.yaml:1:9:", "'colour'", "allowed: cutoff, encoding, exposure, filter", "filter-stddev, height");
        assertMessage(error(BASE.replace("image: {", "image: {filter: mitchell, ")), "s.yaml:1:", "'mitchell'", "allowed: box, gaussian");
        assertMessage(error(BASE.replace("image: {", "image: {filter-stddev: 1, ")), "s.yaml:1:", "'filter-stddev'",
                      "for filter: gaussian, not box");
        assertMessage(error(BASE.replace("image: {", "image: {filter: gaussian, filter-stddev: 3, ")), "s.yaml:1:",
                      "'filter-stddev' in image must be 0.2 to 2.0 pixels, got 3.0");
        assertMessage(error(BASE.replace("image: {", "image: {encoding: gamma, ")), "s.yaml:1:", "gamma", "linear, srgb");
        assertMessage(error(BASE.replace("image: {", "image: {cutoff: -0.1, ")), "s.yaml:1:", "'cutoff'", "at least 0");
        assertMessage(error(BASE.replace("image: {", "image: {cutoff: 1, ")), "s.yaml:1:", "'cutoff'", "below 1");
    }

    @Test
    void otherSectionsAreChecked() {
        assertMessage(error("camera: {fov: 190}\n" + BASE), "s.yaml:1:9:", "field of view");
        assertMessage(error("camera: {type: fisheye}\n" + BASE), "s.yaml:1:16:", "fisheye", "allowed: orthographic, pinhole", "thin-lens");
        assertMessage(error("camera: {type: orthographic, fov: 30}\n" + BASE), "s.yaml:1:30:", "'fov'", "view-height");
        assertMessage(error("camera: {eye: [0, 0, 0], look-at: [0, 0, 0]}\n" + BASE), "s.yaml:1:9:", "must differ");
        // so far apart that the distance's square overflows: w would come out zero, and every ray with it
        assertMessage(error("camera: {eye: [1e307, 1e307, 1e307], look-at: [0, 0, 0]}\n" + BASE), "s.yaml:1:9:", "less than 1e154 apart");
        assertMessage(error("tracer: path\n" + BASE), "s.yaml:1:9:", "'path'", "area-lighting, ray-cast, whitted");
        assertMessage(error("background: [1, -1, 0]\n" + BASE), "s.yaml:1:13:", "negative");
        assertMessage(error("skybox: x\n" + BASE), "s.yaml:1:1:", "'skybox'", "allowed: ambient, background, camera");
        assertMessage(error(BASE.replace("intensity: 10", "intensity: -10")), "s.yaml:5:", "'intensity'");
        assertMessage(error(BASE.replace("{type: point, position: [0, 5, 0], intensity: 10}", "{type: laser}")),
                      "s.yaml:5:", "laser", "allowed: directional, disk, point, rectangle, sphere");
        assertMessage(error(BASE.replace("{type: point, position: [0, 5, 0], intensity: 10}", "{type: point}")),
                      "s.yaml:5:", "needs the key 'position'");
        assertMessage(error(BASE.replace("{type: phong, color: [1, 0, 0]}", "{type: phong, exponent: 0}")),
                      "s.yaml:3:", "'exponent'");
        assertMessage(error(BASE.replace("{type: phong, color: [1, 0, 0]}", "{type: glass}")), "s.yaml:3:", "glass");
    }

    @Test
    void syntaxErrorsEmptyFilesAndMissingObjects() {
        assertMessage(error("objects:\n  - {type: sphere, center: [0, 0, 0\n"), "s.yaml:3:", "syntax error");
        assertMessage(error("objects: [\n  {type: sphere\n"), "s.yaml:", "syntax error");
        assertMessage(error(""), "s.yaml:", "empty");
        assertMessage(error("# only a comment\n"), "s.yaml:", "empty");
        assertMessage(error("image: {width: 8}\n"), "s.yaml:1:1:", "no 'objects'");
        assertMessage(error("- just\n- a list\n"), "s.yaml:1:1:", "mapping");
    }

    @Test
    void fittedModelsByPresetOrValues() throws SceneException {
        String materials = "materials:\n"
            + "  a: {type: ward, preset: nickel}\n  b: {type: ward-duer, preset: delrin, seed-compatible: true}\n"
            + "  c: {type: blinn-phong, rho-d: [0.3, 0.2, 0.1], rho-s: [0.05, 0.05, 0.05], exponent: 80}\n"
            + "objects:\n  - {type: sphere, center: [0, 0, 0], material: a}\n  - {type: sphere, center: [2, 0, 0], material: b}\n"
            + "  - {type: sphere, center: [4, 0, 0], material: c}\n";
        // each sphere's top seen and lit from straight above, irradiance 1 (intensity 4 at distance 2):
        // rho_d / pi plus the lobe at h = n, Ward rho_s / (4 pi a^2), Blinn-Phong rho_s (e + 2) / (2 pi);
        // seed-compatible drops the diffuse 1/pi
        FittedPreset nickel = FittedPreset.of("nickel", FittedPreset.Model.WARD);
        FittedPreset delrin = FittedPreset.of("delrin", FittedPreset.Model.WARD_DUER);
        double[][] expected = new double[3][3];
        for (int c = 0; c < 3; c++) {
            expected[0][c] = channel(nickel.rhoD(), c) / Math.PI
                             + channel(nickel.rhoS(), c) / (4 * Math.PI * nickel.roughness() * nickel.roughness());
            expected[1][c] = channel(delrin.rhoD(), c)
                             + channel(delrin.rhoS(), c) / (4 * Math.PI * delrin.roughness() * delrin.roughness());
            expected[2][c] = new double[] {0.3, 0.2, 0.1}[c] / Math.PI + 0.05 * 82 / (2 * Math.PI);
        }
        for (int i = 0; i < 3; i++) {
            World world = SceneLoader.load("s.yaml", "ambient: {radiance: 0}\nlights: [{type: point, position: ["
                                           + 2 * i + ", 3, 0], intensity: 4}]\n" + materials).world();
            assertRgb(expected[i][0], expected[i][1], expected[i][2], trace(world, 2 * i, 3, 0, 0, -1, 0),
                      "material " + "abc".charAt(i));
        }
        assertMessage(error("materials:\n  a: {type: ward, preset: gold}\nobjects: []\n"), "s.yaml:2:", "'gold'",
                      "delrin, green-acrylic, nickel");
        assertMessage(error("materials:\n  a: {type: ward, exponent: 3}\nobjects: []\n"), "s.yaml:2:", "'exponent'", "alpha");
        assertMessage(error("materials:\n  a: {type: ward, alpha: 0}\nobjects: []\n"), "s.yaml:2:", "'alpha'");
    }

    private static double channel(raytracer.math.RGBColor color, int c) {
        return c == 0 ? color.r() : c == 1 ? color.g() : color.b();
    }

    @Test
    void texturesAndEnvironmentMaps(@TempDir Path dir) throws IOException, SceneException {
        // a Radiance map of 4 x 2 texels, the top row (128 + 0.5) 2^(129 - 136) = 1.00390625, the bottom 0.50390625
        ByteArrayOutputStream hdr = new ByteArrayOutputStream();
        hdr.writeBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n".getBytes(StandardCharsets.US_ASCII));
        for (int i = 0; i < 8; i++) {
            int m = i < 4 ? 128 : 64;
            hdr.writeBytes(new byte[] {(byte) m, (byte) m, (byte) m, (byte) 129});
        }
        Files.write(dir.resolve("sky.hdr"), hdr.toByteArray());
        Files.writeString(dir.resolve("s.yaml"), "environment: {file: sky.hdr, intensity: 0.5}\nambient: {radiance: 0}\n"
            + "materials:\n  floor: {type: matte, texture: {type: checker, size: 0.5}}\n"
            + "  chrome: {type: reflective, kr: 1, reflection-map: {file: sky.hdr}}\n"
            + "objects:\n  - {type: plane, normal: [0, 1, 0], material: floor}\n"
            + "  - {type: sphere, center: [0, 1, 0], material: chrome}\n");
        World world = SceneLoader.load(dir.resolve("s.yaml")).world();
        // the scene's environment, at half intensity: its top row straight up
        assertRgb(0.501953125, 0.501953125, 0.501953125, trace(world, 5, 1, 0, 0, 1, 0), "up");
        // the chrome's own map at full intensity: the sphere's top mirrors the sky straight up
        assertRgb(1.00390625, 1.00390625, 1.00390625, trace(world, 0, 5, 0, 0, -1, 0), "the chrome's top");
        Files.writeString(dir.resolve("bad.yaml"), "materials:\n  m: {type: matte, texture: {type: image, file: missing.png}}\n"
            + "objects: []\n");
        SceneException missing = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("bad.yaml")));
        assertMessage(missing.getMessage(), dir.resolve("bad.yaml") + ":2:", "missing.png", "not found");
        Files.writeString(dir.resolve("env.yaml"), "environment: {file: nowhere.hdr}\nobjects: []\n");
        SceneException env = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("env.yaml")));
        assertMessage(env.getMessage(), dir.resolve("env.yaml") + ":1:", "nowhere.hdr");
    }

    @Test
    void glassAndFresnelMirrors() throws SceneException {
        World world = SceneLoader.load("s.yaml", "background: [1, 1, 1]\nambient: {radiance: 0}\nmaterials:\n"
            + "  glass: {type: dielectric, ior: 1.5, absorption: [0.1, 0, 0.2]}\n"
            + "  brown: {type: reflective, kr: 0.5, fresnel: schlick, reflect-color: [0.6, 0.4, 0.2]}\n"
            + "objects:\n  - {type: sphere, center: [0, 0, 0], material: glass}\n"
            + "  - {type: sphere, center: [3, 0, 0], material: brown}\n").world();
        assertEquals(1.5, ((raytracer.materials.Dielectric) world.objects().get(0).getMaterial()).ior(), 0);
        // glass with the loaded absorption gives what glass built with it gives, and none does not
        World built = SceneLoader.load("s.yaml", "background: [1, 1, 1]\nambient: {radiance: 0}\nobjects: []\n").world();
        raytracer.shapes.Sphere sphere = new raytracer.shapes.Sphere(raytracer.math.Point3D.ORIGIN, 1);
        sphere.setMaterial(new raytracer.materials.Dielectric(1.5, new raytracer.math.RGBColor(0.1, 0, 0.2), 0, 1000));
        built.addObject(sphere);
        MutableRgb loaded = trace(world, 0.3, 0.2, 5, 0, 0, -1);
        MutableRgb expected = trace(built, 0.3, 0.2, 5, 0, 0, -1);
        assertRgb(expected.r, expected.g, expected.b, loaded, "glass");
        assertTrue(loaded.r < loaded.g - 0.05 && loaded.b < loaded.r - 0.05, "red and blue absorbed: " + loaded.r + ", " + loaded.b);
        // the brown Fresnel mirror in a white world without lights: Schlick's kr + (1 - kr)(1 - cos)^5 of its colour
        assertRgb(0.3, 0.2, 0.1, trace(world, 3, 5, 0, 0, -1, 0), "mirror at normal incidence");
        double grazing = 0.5 + 0.5 * Math.pow(0.5, 5);
        assertRgb(0.6 * grazing, 0.4 * grazing, 0.2 * grazing, trace(world, 3 + Math.sqrt(0.75), 5, 0, 0, -1, 0), "mirror at 60 degrees");
        assertMessage(error("materials:\n  g: {type: dielectric, ior: 0}\n" + "objects: []\n"), "s.yaml:2:", "'ior'");
        assertMessage(error("materials:\n  g: {type: dielectric, absorption: [0, -1, 0]}\nobjects: []\n"), "s.yaml:2:", "negative");
        assertMessage(error("materials:\n  m: {type: reflective, fresnel: exact}\nobjects: []\n"), "s.yaml:2:", "'exact'", "none, schlick");
        assertMessage(error("materials:\n  g: {type: dielectric, kd: 1}\nobjects: []\n"), "s.yaml:2:", "'kd'", "absorption, exponent, ior");
    }

    @Test
    void meshesLoadRelativeToTheSceneWithTheirMtlMaterials(@TempDir Path dir) throws IOException, SceneException {
        Files.createDirectories(dir.resolve("models"));
        Files.writeString(dir.resolve("models/quad.mtl"), "newmtl shiny\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 40\n");
        Files.writeString(dir.resolve("models/quad.obj"), "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl shiny\nf 1 2 3 4\n");
        Files.writeString(dir.resolve("scene.yaml"), "objects:\n  - {type: mesh, file: models/quad.obj, smooth: true, bvh: sah}\n");
        LoadedScene loaded = SceneLoader.load(dir.resolve("scene.yaml"));
        World world = loaded.world();
        world.prepare();
        raytracer.accel.MeshBVH mesh = (raytracer.accel.MeshBVH) world.objects().get(0);
        assertEquals(2, mesh.mesh().triangleCount());
        assertTrue(mesh.mesh().hasNormals(), "smooth: true computes vertex normals");
        assertTrue(mesh.getMaterial() instanceof raytracer.materials.Phong, "Ks and Ns make a Phong material");
        Map<String, Long> timings = loaded.report().timings();
        assertTrue(timings.keySet().stream().anyMatch(k -> k.startsWith("parse quad.obj")), timings.toString());
        Map<String, Long> prepared = loaded.report().prepareTimings();
        assertTrue(prepared.keySet().stream().anyMatch(k -> k.startsWith("sah BVH of quad.obj")), prepared.toString());
    }

    @Test
    void meshErrorsNameTheSceneAndTheMeshFile(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
        Files.writeString(dir.resolve("a.yaml"), "objects:\n  - {type: mesh, file: missing.obj}\n");
        Files.writeString(dir.resolve("b.yaml"), "objects:\n  - {type: mesh, file: bad.obj}\n");
        Files.writeString(dir.resolve("c.yaml"), "objects:\n  - {type: mesh, file: bad.obj, bvh: kd-tree}\n");
        SceneException missing = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("a.yaml")));
        assertMessage(missing.getMessage(), dir.resolve("a.yaml") + ":2:", "missing.obj", "no such file");
        SceneException bad = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("b.yaml")));
        assertMessage(bad.getMessage(), dir.resolve("b.yaml") + ":2:", "bad.obj:3: vertex index 3 is out of range");
        SceneException builder = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("c.yaml")));
        assertMessage(builder.getMessage(), dir.resolve("c.yaml") + ":2:", "kd-tree", "median, sah");
    }

    @Test
    void unreadableFiles(@TempDir Path dir) {
        SceneException missing = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("nope.yaml")));
        assertMessage(missing.getMessage(), "cannot read scene file", "nope.yaml", "no such file");
        SceneException folder = assertThrows(SceneException.class, () -> SceneLoader.load(dir));
        assertMessage(folder.getMessage(), "cannot read scene file", "directory");
    }
}

package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.accel.Aggregation;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;

/**
 * Each decision of the scene analysis is exact: the scene is rendered with the analysis and
 * without it, and the two PFM files must be the same bytes. Each test also checks that the
 * decision was taken where it may be (and counted what it saved), or declined where it may not,
 * in a scene built so that a wrong decision would change pixels.
 */
class SceneAnalysisTest {
    private static final String VIEW = "image: {width: 32, height: 24, samples: 4}\n"
                                       + "camera: {eye: [0, 2, 8], look-at: [0, 0.5, 0], fov: 40}\n";

    @TempDir
    Path dir;

    /** What both renders gave: the decisions, and the stats without and with them. */
    private record Outcome(List<Skip> skips, RenderStats without, RenderStats with, World analysed) {
        boolean decided(String what) {
            return skips.stream().anyMatch(s -> s.what().contains(what));
        }

        String list() {
            return skips.toString();
        }
    }

    private Outcome both(String yaml) throws IOException, SceneException {
        return both(yaml, Aggregation.Mode.LIST);
    }

    /** As {@link #both(Path)}, the objects searched as {@code accel} groups them (a BVH, or a list). */
    private Outcome both(String yaml, Aggregation.Mode accel) throws IOException, SceneException {
        Path scene = Files.writeString(dir.resolve("s.yaml"), yaml);
        return both(scene, accel);
    }

    private Outcome both(Path scene) throws IOException, SceneException {
        return both(scene, Aggregation.Mode.LIST);
    }

    /** Renders the scene as given and after the analysis, and checks that their PFMs are the same bytes. */
    private Outcome both(Path scene, Aggregation.Mode accel) throws IOException, SceneException {
        LoadedScene plain = SceneLoader.load(scene);
        LoadedScene analysed = SceneLoader.load(scene);
        SceneAnalysis analysis = SceneAnalysis.apply(analysed.world(), analysed.rayTree());
        RenderStats without = render(plain, dir.resolve("without.pfm"), accel);
        RenderStats with = render(analysed, dir.resolve("with.pfm"), accel);
        assertArrayEquals(Files.readAllBytes(dir.resolve("without.pfm")), Files.readAllBytes(dir.resolve("with.pfm")),
                          "the analysis changed the image; it decided " + analysis.skips());
        assertEquals(0, with.nonFiniteSamples());
        return new Outcome(analysis.skips(), without, with, analysed.world());
    }

    private static RenderStats render(LoadedScene scene, Path pfm, Aggregation.Mode accel) throws IOException {
        World world = scene.world();
        world.prepare(objects -> Aggregation.organize(objects, accel));
        Film film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
        RenderStats stats = Renders.render(world, scene.rayTree(), 2, 7, film);
        ImageWriters.write(film, world.viewPlane().exposure(), pfm);
        return stats;
    }

    // ---- shadow rays ----

    @Test
    void aLoneFloorNeedsNoShadowRays() throws IOException, SceneException {
        Outcome o = both(VIEW + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                         + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n");
        assertTrue(o.decided("no shadow rays towards light 1 (point light)"), o.list());
        assertEquals(0, o.with().shadowRays());
        assertTrue(o.without().shadowRays() > 0);
        assertEquals(o.without().shadowRays(), o.with().skipped(Skipped.SHADOW_RAYS), "every ray left out is counted");
    }

    @Test
    void aLoneSphereNeedsNoShadowRaysFromAnAreaLight() throws IOException, SceneException {
        // the light's samples are drawn as before: only the shadow rays go
        Outcome o = both(VIEW + "lights:\n  - {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], "
                         + "radiance: 5, samples: 4, visible: false}\n"
                         + "objects:\n  - {type: sphere, center: [0, 0.5, 0], radius: 1}\n");
        assertTrue(o.decided("no shadow rays towards light 1 (rectangle light)"), o.list());
        assertEquals(o.without().shadowRays(), o.with().skipped(Skipped.SHADOW_RAYS));
    }

    @Test
    void aSphereOnTheFloorKeepsItsShadowRays() throws IOException, SceneException {
        Outcome o = both(VIEW + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                         + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [0, 1, 0], radius: 1}\n");
        assertFalse(o.decided("shadow rays"), o.list());
        assertEquals(o.without().shadowRays(), o.with().shadowRays());
    }

    @Test
    void objectsCutOffFromEachOtherAndTheLightCannotShadowEachOther() throws IOException, SceneException {
        String spheres = "objects:\n  - {type: sphere, center: [-2, 0, 0], radius: 1}\n"
                         + "  - {type: sphere, center: [2, 3, 0], radius: 1}\n";
        String view = "image: {width: 32, height: 24, samples: 4}\ncamera: {eye: [0, 1.5, 12], look-at: [0, 1.5, 0], fov: 40}\n";
        // from the upper left, the high sphere is right of the low one and the low one below the high one
        Outcome apart = both(view + "lights:\n  - {type: point, position: [-10, 10, 0], intensity: 300}\n" + spheres);
        assertTrue(apart.decided("no shadow rays towards light 1"), apart.list());
        // from the upper right, the high sphere stands between the low one and the light
        Outcome between = both(view + "lights:\n  - {type: point, position: [10, 10, 0], intensity: 300}\n" + spheres);
        assertFalse(between.decided("shadow rays"), between.list());
    }

    @Test
    void aSphereSeenFromInsideShadowsItself() throws IOException, SceneException {
        // the camera inside, the light outside: the far wall's inner side faces the light and is in the sphere's shadow
        Outcome o = both("image: {width: 32, height: 24, samples: 4}\ncamera: {eye: [0, 0, 0], look-at: [0, 0, -1], fov: 60}\n"
                         + "lights:\n  - {type: point, position: [0, 0, 6], intensity: 30}\n"
                         + "objects:\n  - {type: sphere, center: [0, 0, 0], radius: 3}\n");
        assertFalse(o.decided("shadow rays"), o.list());
        assertTrue(o.with().shadowRays() > 0);
    }

    // ---- zero terms ----

    @Test
    void aPhongWithoutHighlightRendersAsAMatte() throws IOException, SceneException {
        String rest = "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                      + "objects:\n  - {type: plane, normal: [0, 1, 0], material: m}\n  - {type: sphere, center: [0, 1, 0], radius: 1, material: m}\n";
        Outcome phong = both(VIEW + "materials:\n  m: {type: phong, ka: 0.2, kd: 0.7, color: [0.8, 0.5, 0.3], ks: 0, exponent: 30}\n" + rest);
        assertTrue(phong.decided("specular lobe not evaluated"), phong.list());
        assertTrue(phong.with().skipped(Skipped.SPECULAR_LOBES) > 0);
        byte[] phongImage = Files.readAllBytes(dir.resolve("with.pfm"));
        both(VIEW + "materials:\n  m: {type: matte, ka: 0.2, kd: 0.7, color: [0.8, 0.5, 0.3]}\n" + rest);
        assertArrayEquals(Files.readAllBytes(dir.resolve("with.pfm")), phongImage, "a Phong with ks = 0 is a matte");
    }

    @Test
    void zeroAmbientZeroDiffuseAndConstantTexturesAreNotEvaluated() throws IOException, SceneException {
        Outcome o = both(VIEW + "ambient: {radiance: 0}\n"
                         + "materials:\n  shiny: {type: phong, kd: 0, ks: 0.5, exponent: 20}\n"
                         + "  flat: {type: matte, texture: {type: constant, color: [0.3, 0.6, 0.2]}}\n"
                         + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                         + "objects:\n  - {type: plane, normal: [0, 1, 0], material: flat}\n"
                         + "  - {type: sphere, center: [0, 1, 0], radius: 1, material: shiny}\n");
        assertTrue(o.decided("ambient term not evaluated") && o.decided("diffuse term not evaluated")
                   && o.decided("constant texture read as a plain colour"), o.list());
        assertTrue(o.with().skipped(Skipped.AMBIENT_TERMS) > 0 && o.with().skipped(Skipped.DIFFUSE_TERMS) > 0);
    }

    @Test
    void clearGlassWithoutHighlightTakesNoLightSamples() throws IOException, SceneException {
        // glass with ks = 0 reflects no direct light: its lights are not evaluated, its shadow rays not traced
        Outcome o = both(VIEW + "materials:\n  glass: {type: dielectric, ior: 1.5}\n"
                         + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                         + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [0, 1, 0], radius: 1, material: glass}\n");
        assertTrue(o.decided("lights not evaluated"), o.list());
        assertTrue(o.with().skipped(Skipped.LIGHT_SAMPLES) > 0);
        assertTrue(o.with().shadowRays() < o.without().shadowRays());
        assertTrue(o.without().shadowRays() - o.with().shadowRays() <= o.with().skipped(Skipped.LIGHT_SAMPLES),
                   "each shadow ray saved was a light sample left out (samples facing away traced none)");
    }

    @Test
    void aMirrorOfWeightZeroTracesNoRaysUnlessSomethingDrawsSamples() throws IOException, SceneException {
        String objects = "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [0, 1, 0], radius: 1, material: dull}\n";
        String dull = "materials:\n  dull: {type: reflective, kr: 0, ks: 0.2}\n";
        Outcome o = both(VIEW + dull + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n" + objects);
        assertTrue(o.decided("mirror rays of weight 0 not traced"), o.list());
        assertTrue(o.decided("max depth 5 -> 0"), "then no material traces: " + o.list());
        assertEquals(0, o.with().secondaryRays());
        assertEquals(o.without().secondaryRays(), o.with().skipped(Skipped.SECONDARY_RAYS));
        // an area light draws samples at every hit: a ray left out would move the draws after it
        Outcome area = both(VIEW + dull + "lights:\n  - {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], "
                            + "edge-b: [0, 0, 2], radiance: 5, samples: 4}\n" + objects);
        assertFalse(area.decided("mirror rays"), area.list());
        assertEquals(area.without().secondaryRays(), area.with().secondaryRays());
        // with Schlick's Fresnel a mirror of kr = 0 still reflects at grazing angles
        Outcome schlick = both(VIEW + "materials:\n  dull: {type: reflective, kr: 0, fresnel: schlick}\n"
                               + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n" + objects);
        assertFalse(schlick.decided("mirror rays"), schlick.list());
    }

    // ---- recursion ----

    @Test
    void noMaterialThatTracesMeansNoRecursion() throws IOException, SceneException {
        Outcome o = both(VIEW + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                         + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [0, 1, 0], radius: 1}\n");
        assertTrue(o.decided("max depth 5 -> 0"), o.list());
        assertEquals(0, o.analysed().viewPlane().maxDepth());
    }

    @Test
    void aRayCastOrADirectPassCutsTheRecursionOfMirrors() throws IOException, SceneException {
        String mirror = "materials:\n  m: {type: reflective, kr: 0.8}\n"
                        + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                        + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [0, 1, 0], radius: 1, material: m}\n";
        Outcome rayCast = both(VIEW + "tracer: ray-cast\n" + mirror);
        assertTrue(rayCast.decided("max depth 5 -> 0"), rayCast.list());
        assertTrue(rayCast.without().secondaryRays() > 0);
        assertEquals(0, rayCast.with().secondaryRays());
        Outcome direct = both(VIEW + "pass: direct\n" + mirror);
        assertTrue(direct.decided("max depth 5 -> 0"), direct.list());
        Outcome full = both(VIEW + mirror);
        assertFalse(full.decided("max depth"), full.list());
        // a glossy material draws its rays' directions before the tracer could return black: kept
        Outcome glossy = both(VIEW + "tracer: ray-cast\n" + mirror.replace("{type: reflective, kr: 0.8}",
                                                                          "{type: glossy, ks: 0.5, exponent: 50, samples: 4}"));
        assertFalse(glossy.decided("max depth"), glossy.list());
    }

    // ---- lights ----

    @Test
    void lightsThatEmitNothingAreLeftOutOrKeepTheirDraws() throws IOException, SceneException {
        // the dark rectangle comes first: leaving it out would move the other light's samples
        Outcome o = both(VIEW + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 0}\n"
                         + "  - {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], radiance: 0, samples: 4}\n"
                         + "  - {type: rectangle, corner: [1, 3, -1], edge-a: [1, 0, 0], edge-b: [0, 0, 1], radiance: 9, samples: 4}\n"
                         + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [0, 1, 0], radius: 1}\n");
        assertTrue(o.decided("light 1 (point light) left out"), o.list());
        assertTrue(o.decided("no shadow rays towards light 2 (rectangle light)"), o.list());
        assertEquals(2, o.analysed().lights().length);
    }

    @Test
    void lightsBehindAnOpaqueFloorAreLeftOut() throws IOException, SceneException {
        String scene = VIEW + "materials:\n  glass: {type: dielectric, ior: 1.5}\n"
                       + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                       + "  - {type: point, position: [0.5, -0.01, 0.5], intensity: 30}\n"
                       + "  - {type: directional, direction: [0.3, -1, 0.2], radiance: 0.5}\n"
                       + "  - {type: directional, direction: [1, 0.0001, 0], radiance: 0.5}\n"
                       + "objects:\n  - {type: plane, normal: [0, 1, 0]%s}\n  - {type: sphere, center: [0, 1.1, 0], radius: 1}\n%s";
        Outcome below = both(scene.formatted("", ""));
        assertTrue(below.decided("light 2 (point light) left out"), below.list());
        assertTrue(below.decided("light 3 (directional light) left out"), below.list());
        assertFalse(below.decided("light 4"), below.list());
        assertEquals(2, below.analysed().lights().length);
        // the floor's normal the other way round: the same plane, the same decision
        assertTrue(both(scene.formatted("", "").replace("normal: [0, 1, 0]", "normal: [0, -1, 0]"))
                       .decided("light 2 (point light) left out"));
        // a floor of glass lets light through; one that casts no shadow does not stop it
        Outcome glass = both(scene.formatted(", material: glass", ""));
        assertFalse(glass.decided("left out"), glass.list());
        Outcome noShadow = both(scene.formatted(", casts-shadows: false", ""));
        assertFalse(noShadow.decided("left out"), noShadow.list());
        // an object below the floor may be lit from below, and seen through nothing: kept anyway
        Outcome under = both(scene.formatted("", "  - {type: sphere, center: [3, -2, 0], radius: 0.5}\n"));
        assertFalse(under.decided("point light) left out"), under.list());
        // a sphere that touches the floor: its lowest points, within rounding of the plane, could be lit from below
        Outcome touching = both(scene.formatted("", "").replace("center: [0, 1.1, 0]", "center: [0, 1, 0]"));
        assertFalse(touching.decided("left out"), touching.list());
        // a light 1e-17 below the floor, beyond it at its own scale but not at the scene's: a shadow
        // ray's length and the floor's distance along it come out alike, and the sphere was lit
        Outcome grazing = both(scene.formatted("", "").replace("position: [0.5, -0.01, 0.5]", "position: [0, -1e-17, 0]"));
        assertFalse(grazing.decided("light 2"), grazing.list());
        // a tilted floor: its far hits are off the plane by rounding that grows with their distance
        String tilted = scene.formatted("", "").replace("normal: [0, 1, 0]", "normal: [0.1, 1, 0.2]")
                             .replace("center: [0, 1.1, 0]", "center: [0, 1.6, 0]");
        Outcome tiltedBelow = both(tilted);
        assertFalse(tiltedBelow.decided("light 2"), tiltedBelow.list());
        assertTrue(tiltedBelow.decided("light 3 (directional light) left out"), tiltedBelow.list());
        Outcome tiltedGrazing = both(tilted.replace("position: [0.5, -0.01, 0.5]", "position: [-1e-18, -1e-17, -2e-18]"));
        assertFalse(tiltedGrazing.decided("light 2"), tiltedGrazing.list());
        // a light without shadows lights the sphere through the floor
        Outcome unshadowed = both(scene.formatted("", "").replace("position: [0.5, -0.01, 0.5], intensity: 30}",
                                                                  "position: [0.5, -0.01, 0.5], intensity: 30, shadows: false}"));
        assertFalse(unshadowed.decided("light 2"), unshadowed.list());
    }

    // ---- objects no ray reaches ----

    @Test
    void anObjectOutsideTheViewIsLeftOutUnlessItsShadowCanFallIntoIt() throws IOException, SceneException {
        String view = VIEW + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n  - {type: sphere, center: [30, 1, 0], radius: 1}\n";
        // the light right of the view's face on that side: the sphere's shadow may fall into the view
        Outcome shadow = both(view.replace("objects:", "lights:\n  - {type: point, position: [60, 2, 0], intensity: 3000}\nobjects:"));
        assertFalse(shadow.decided("left out"), shadow.list());
        Outcome apart = both(view.replace("objects:", "lights:\n  - {type: point, position: [0, 4, 2], intensity: 30}\nobjects:"));
        assertTrue(apart.decided("sphere left out"), apart.list());
        assertEquals(1, apart.analysed().objects().size());
        // a mirror could show it: kept
        Outcome mirror = both(view.replace("objects:", "materials:\n  m: {type: reflective}\n"
                                           + "lights:\n  - {type: point, position: [0, 4, 2], intensity: 30}\nobjects:")
                                  .replace("normal: [0, 1, 0]}", "normal: [0, 1, 0], material: m}"));
        assertFalse(mirror.decided("left out"), mirror.list());
    }

    @Test
    void aMeshOutsideTheViewIsNeverBuilt() throws IOException, SceneException {
        Files.writeString(dir.resolve("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        String scene = VIEW + "lights:\n  - {type: point, position: [0, 4, 2], intensity: 30}\n"
                       + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n"
                       + "  - {type: mesh, file: tri.obj, transform: [{translate: [%s, 1, 0]}]}\n";
        Outcome out = both(Files.writeString(dir.resolve("out.yaml"), scene.formatted("-40")));
        assertTrue(out.decided("instance of mesh tri.obj left out (not built, not traced)"), out.list());
        LoadedScene loaded = SceneLoader.load(dir.resolve("out.yaml"));
        SceneAnalysis.apply(loaded.world(), loaded.rayTree());
        loaded.world().prepare();
        assertTrue(loaded.report().prepareTimings().isEmpty(), "nothing built: " + loaded.report().prepareTimings());
        LoadedScene in = SceneLoader.load(Files.writeString(dir.resolve("in.yaml"), scene.formatted("0")));
        SceneAnalysis.apply(in.world(), in.rayTree());
        in.world().prepare();
        assertTrue(in.report().prepareTimings().keySet().stream().anyMatch(k -> k.startsWith("sah BVH of tri.obj")),
                   in.report().prepareTimings().toString());
    }

    // ---- texture coordinates ----

    @Test
    void untexturedSpheresAndCylindersLeaveOutTheirTextureCoordinates() throws IOException, SceneException {
        String scene = VIEW + "materials:\n  m: {type: matte, %s}\n"
                       + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                       + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n"
                       + "  - {type: sphere, center: [-1, 1, 0], radius: 1, material: m}\n"
                       + "  - {type: cylinder, radius: 0.5, top: 2, transform: [{translate: [1.5, 0, 0]}], material: m}\n";
        Outcome plain = both(scene.formatted("color: [0.8, 0.5, 0.2]"));
        assertTrue(plain.decided("u, v of hits not computed"), plain.list());
        assertTrue(plain.with().skipped(Skipped.TEXTURE_COORDINATES) > 0);
        assertEquals(0, plain.without().skipped(Skipped.TEXTURE_COORDINATES), "computed when not decided");
        Outcome constant = both(scene.formatted("texture: {type: constant, color: [0.8, 0.5, 0.2]}"));
        assertTrue(constant.decided("u, v of hits not computed"), constant.list());
        // a checker on both shapes: u, v left out would paint them in one colour
        Outcome checker = both(scene.formatted("texture: {type: checker, size: 0.2}"));
        assertFalse(checker.decided("u, v"), checker.list());
        assertEquals(0, checker.with().skipped(Skipped.TEXTURE_COORDINATES));
    }
    // ---- objects a tile's camera rays cannot hit ----

    @Test
    void cameraRaysTestOnlyTheObjectsTheirTileSees() throws IOException, SceneException {
        // 160 x 96 pixels, 5 x 3 tiles; small spheres in three corners and the middle, over a floor
        String scene = "image: {width: 160, height: 96, samples: 2}\n"
                       + "camera: {%s, eye: [0, 2, 8], look-at: [0, 0.5, 0]}\n"
                       + "lights:\n  - {type: point, position: [1, 4, 2], intensity: 30}\n"
                       + "objects:\n  - {type: plane, normal: [0, 1, 0]}\n"
                       + "  - {type: sphere, center: [-2.6, 1.9, 0], radius: 0.3}\n"
                       + "  - {type: sphere, center: [2.6, 1.9, 0], radius: 0.3}\n"
                       + "  - {type: sphere, center: [-2.6, 0.3, 1], radius: 0.3}\n"
                       + "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5}\n";
        for (String camera : new String[] {"fov: 40", "type: thin-lens, fov: 40, lens-radius: 0.05, focal-distance: 8",
                                           "type: orthographic, view-height: 4"}) {
            Outcome o = both(scene.formatted(camera));
            assertTrue(o.decided("camera rays test only the objects, and the parts of a BVH, that their tile can see"), o.list());
            long tests = 5 * o.with().primaryRays();
            long skipped = o.with().skipped(Skipped.OBJECT_TESTS);
            // each corner sphere lies in one or two of the 15 tiles, the middle one in a few
            assertTrue(skipped > tests / 2 && skipped < tests, camera + ": " + skipped + " of " + tests + " tests skipped");
            assertEquals(0, o.without().skipped(Skipped.OBJECT_TESTS), "not skipped when not decided");
        }
        // the same spheres and 40 more in a BVH: its search starts, tile by tile, where the tile's view leads
        StringBuilder more = new StringBuilder();
        for (int k = 0; k < 40; k++) {
            more.append("  - {type: sphere, center: [").append(-3 + 0.15 * k).append(", ").append(0.3 + 0.04 * k)
                .append(", ").append(-1 - 0.05 * k).append("], radius: 0.12}\n");
        }
        Outcome bvh = both(scene.formatted("fov: 40") + more, Aggregation.Mode.MEDIAN);
        assertTrue(bvh.decided("camera rays test only the objects"), bvh.list());
        assertTrue(bvh.with().boxTests() < bvh.without().boxTests(),
                   bvh.with().boxTests() + " box tests against " + bvh.without().boxTests());
    }
}

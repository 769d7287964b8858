package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.math.RGBColor;
import raytracer.reference.LitPlane;
import raytracer.reference.ParallelDiskLight;
import raytracer.reference.PolygonLight;

/** Which scenes have an exact image, what is read from them, and one clear line for those that have none. */
class ClosedFormReaderTest {
    private static final String SCENE = """
        image: {width: 20, height: 10, exposure: 2}
        ambient: {radiance: 0.5, color: [1, 0.5, 1]}
        camera: {type: orthographic, eye: [0, 3, 0], look-at: [0, 0, 0], up: [0, 0, -1], view-height: 6}
        materials:
          floor: {type: matte, ka: 0.1, kd: 0.7, color: [1, 0.5, 0.25]}
        lights:
          - {type: rectangle, corner: [-1, 1.5, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 1], radiance: 4, color: [1, 1, 0.5], visible: false}
        objects:
          - {type: plane, normal: [0, 2, 0], material: floor}
        """;

    private static void assertColor(RGBColor expected, RGBColor actual) {
        assertEquals(expected.r(), actual.r(), 1e-15);
        assertEquals(expected.g(), actual.g(), 1e-15);
        assertEquals(expected.b(), actual.b(), 1e-15);
    }

    @Test
    void readsTheValuesTheImageDependsOn() throws SceneException {
        LitPlane p = ClosedFormReader.read("s.yaml", SCENE);
        assertEquals(20, p.width());
        assertEquals(10, p.height());
        assertEquals(2, p.exposure(), 0);
        assertEquals(6, p.viewHeight(), 0);
        assertColor(new RGBColor(0.7, 0.35, 0.175), p.diffuse());
        // ka cd La: 0.1 (1, 0.5, 0.25) 0.5 (1, 0.5, 1)
        assertColor(new RGBColor(0.05, 0.0125, 0.0125), p.ambient());
        assertColor(new RGBColor(4, 4, 2), p.lightRadiance());
        assertEquals(1, p.planeNormal().y(), 0, "the normal is made a unit vector");
        assertTrue(p.light() instanceof PolygonLight);
    }

    @Test
    void defaultsAreTheLoadersDefaults() throws SceneException {
        LitPlane p = ClosedFormReader.read("s.yaml", """
            camera: {type: orthographic, up: [0, 0, -1], eye: [0, 3, 0], look-at: [0, 0, 0]}
            lights:
              - {type: disk, center: [0, 1, 0], normal: [0, -1, 0], visible: false}
            objects:
              - {type: plane, normal: [0, 1, 0]}
            """);
        assertEquals(640, p.width());
        assertEquals(360, p.height());
        assertEquals(CameraReader.DEFAULT_VIEW_HEIGHT, p.viewHeight(), 0);
        // the default material is matte grey 0.8 with ka 0.2, kd 0.8; the default ambient light 0.1 white
        assertColor(RGBColor.gray(0.8 * 0.8), p.diffuse());
        assertColor(RGBColor.gray(0.2 * 0.8 * 0.1), p.ambient());
        assertColor(RGBColor.WHITE, p.lightRadiance());
        assertTrue(p.light() instanceof ParallelDiskLight);
    }

    @Test
    void theShippedScenesHaveExactImages() throws SceneException {
        for (String name : new String[] {"closed-form-rectangle", "closed-form-disk"}) {
            LitPlane p = ClosedFormReader.read(Path.of("scenes", name + ".yaml"));
            assertEquals(512, p.width(), name);
        }
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "type: orthographic, eye: [0, 3, 0], look-at: [0, 0, 0], up: [0, 0, -1], view-height: 6|eye: [0, 3, 0], look-at: [0, 0, 0]"
            + "|3:9: no closed form: the camera must be orthographic",
        "floor: {type: matte,|floor: {type: phong,|5:10: no closed form: the plane's material must be matte",
        "color: [1, 0.5, 0.25]}|texture: {type: constant, color: [1, 1, 1]}}|5:51: no closed form: the plane's material must have no texture",
        "visible: false|visible: true|7:5: no closed form: the light must be 'visible: false'",
        "normal: [0, 2, 0], material: floor}|normal: [0, 2, 0], material: floor, transform: [{translate: [0, 1, 0]}]}"
            + "|9:66: no closed form: the plane must have no transform",
        "corner: [-1, 1.5, -1]|corner: [-1, -0.5, -1]|1:1: no closed form: the light must lie wholly above the plane",
        "up: [0, 0, -1]|up: [0, -1, 0]|1:1: no closed form: the camera needs an eye apart from its look-at point and an up vector"})
    void scenesWithoutAnExactImageSaySoInOneLine(String from, String to, String message) {
        String text = SCENE.replace(from, to);
        assertTrue(!text.equals(SCENE), "the test's edit did not apply: " + from);
        SceneException e = assertThrows(SceneException.class, () -> ClosedFormReader.read("s.yaml", text));
        assertTrue(e.getMessage().startsWith("s.yaml:" + message), e.getMessage());
    }

    @Test
    void aTiltedDiskASecondLightOrASecondObjectHasNone() {
        String disk = SCENE.replace("{type: rectangle, corner: [-1, 1.5, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 1]",
                                    "{type: disk, center: [0, 1, 0], normal: [0.1, -1, 0]");
        SceneException e = assertThrows(SceneException.class, () -> ClosedFormReader.read("s.yaml", disk));
        assertTrue(e.getMessage().contains("no closed form: a disk light must be parallel to the plane and face it"), e.getMessage());
        String two = SCENE.replace("lights:\n", "lights:\n  - {type: point, position: [0, 1, 0]}\n");
        e = assertThrows(SceneException.class, () -> ClosedFormReader.read("s.yaml", two));
        assertTrue(e.getMessage().contains("no closed form: the scene must have exactly one light"), e.getMessage());
        String twoObjects = SCENE.replace("  - {type: plane", "  - {type: sphere, center: [0, 0, 0]}\n  - {type: plane");
        e = assertThrows(SceneException.class, () -> ClosedFormReader.read("s.yaml", twoObjects));
        assertTrue(e.getMessage().startsWith("s.yaml:9:3: no closed form: the scene must hold one object, a plane"), e.getMessage());
        // a scene the loader refuses is refused for that reason first
        e = assertThrows(SceneException.class, () -> ClosedFormReader.read("s.yaml", SCENE.replace("radiance: 4", "radiance: -4")));
        assertTrue(e.getMessage().contains("'radiance' in rectangle light must be at least 0"), e.getMessage());
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.accel.MeshBVH;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.math.Point3D;
import raytracer.render.Renders;
import raytracer.shapes.Instance;

/**
 * The animation section: tracks hit their keys and interpolate as stated (linear, and the smooth
 * Hermite curve, against values worked out by hand), the orbit keeps the eye's distance and turns at
 * an even rate, object motion follows the object's own transform, each frame is a world of its own
 * while meshes are shared by every frame, and a wrong section is one message naming file and line.
 */
class AnimationTest {
    @TempDir
    Path dir;

    @Test
    void linearTrackHitsItsKeysAndHoldsBeyondThem() {
        Track t = new Track(new double[] {0, 10, 30}, new double[][] {{0}, {5}, {-5}}, false);
        assertEquals(0, t.at(-3)[0]);
        assertEquals(2.5, t.at(5)[0], 1e-15);
        assertEquals(5, t.at(10)[0]);
        assertEquals(0, t.at(20)[0], 1e-15);
        assertEquals(-5, t.at(99)[0]);
    }

    @Test
    void smoothTrackIsSmoothstepBetweenTwoKeysAndHasNoKinkAtAnInnerKey() {
        Track two = new Track(new double[] {0, 4}, new double[][] {{0}, {1}}, true);
        // 3 s^2 - 2 s^3 at s = 1/4, 1/2
        assertEquals(3.0 / 16 - 2.0 / 64, two.at(1)[0], 1e-15);
        assertEquals(0.5, two.at(2)[0], 1e-15);
        Track three = new Track(new double[] {0, 10, 40}, new double[][] {{0}, {6}, {3}}, true);
        assertEquals(6, three.at(10)[0], 1e-12);
        // the slope on either side of the inner key is its Catmull-Rom tangent (3 - 0) / (40 - 0)
        double h = 1e-5;
        double left = (three.at(10)[0] - three.at(10 - h)[0]) / h;
        double right = (three.at(10 + h)[0] - three.at(10)[0]) / h;
        assertEquals(3.0 / 40, left, 1e-4);
        assertEquals(3.0 / 40, right, 1e-4);
        // and it eases in and out at the ends
        assertEquals(0, (three.at(h)[0] - three.at(0)[0]) / h, 1e-3);
    }

    private SceneFile scene(String animation) throws IOException, SceneException {
        Path file = Files.writeString(dir.resolve("a.yaml"), """
            image: {width: 16, height: 12, samples: 1}
            camera: {eye: [0, 1, 6], look-at: [0, 1, 0], fov: 40}
            lights:
              - {type: point, position: [2, 6, 4], intensity: 60}
            objects:
              - {type: plane, normal: [0, 1, 0]}
              - {type: box, name: crate, min: [-0.5, 0, -0.5], max: [0.5, 1, 0.5], transform: [{translate: [1, 0, 0]}]}
            """ + animation);
        return SceneFile.read(file, null);
    }

    @Test
    void orbitTurnsTheEyeAroundTheCentreAtAnEvenRate() throws Exception {
        SceneFile s = scene("""
            animation:
              frames: 8
              camera: {orbit: {center: [0, 1, 0]}}
            """);
        assertEquals(8, s.frames());
        assertEquals(24, s.fps());
        Source x = new Source("x", null);
        Node base = SceneLoader.root(x, "{eye: [0, 1, 6], look-at: [0, 1, 0], fov: 40}");
        Animation a = Animation.read(x, SceneLoader.root(x, """
            frames: 8
            camera: {orbit: {center: [0, 1, 0], degrees: 360}}
            """), false);
        for (int f = 0; f < 8; f++) {
            YamlObject camera = new YamlObject(x, a.camera(x, base, f), "camera", AnyName.INSTANCE);
            assertEquals(40, camera.number("fov", 0), "what is not animated stays");
            Point3D eye = camera.point("eye", null);
            double angle = Math.toRadians(45 * f);
            // rotate-y by angle takes (0, 0, 6) to (6 sin, 0, 6 cos)
            assertEquals(6 * Math.sin(angle), eye.x(), 1e-12);
            assertEquals(1, eye.y(), 1e-12);
            assertEquals(6 * Math.cos(angle), eye.z(), 1e-12);
        }
    }

    @Test
    void cameraKeysGiveTheirValuesAtTheirFramesAndKeepTheRestOfTheCamera() throws Exception {
        Source x = new Source("x", null);
        Animation a = Animation.read(x, SceneLoader.root(x, """
            frames: 31
            fps: 10
            camera:
              interpolation: smooth
              keys:
                - {frame: 0, eye: [0, 1, 6], fov: 40}
                - {time: 1, eye: [3, 2, 6]}
                - {frame: 30, eye: [6, 1, 0], fov: 20}
            """), false);
        assertEquals(new Point3D(3, 2, 6), camera(a, 10).point("eye", null), "time 1 s at 10 fps is frame 10");
        assertEquals(new Point3D(6, 1, 0), camera(a, 30).point("eye", null));
        assertEquals(30, camera(a, 15).number("fov", 0), 1e-12, "fov keys at 0 and 30 only: smoothstep's midpoint");
        assertEquals(new Point3D(0, 2, 0), camera(a, 15).point("look-at", null), "look-at is not animated");
    }

    private static YamlObject camera(Animation a, int frame) throws SceneException {
        Source x = new Source("x", null);
        Node base = SceneLoader.root(x, "{type: thin-lens, look-at: [0, 2, 0], lens-radius: 0.1}");
        return new YamlObject(x, a.camera(x, base, frame), "camera", AnyName.INSTANCE);
    }

    @Test
    void objectMotionFollowsTheObjectsOwnTransform() throws Exception {
        SceneFile s = scene("""
            animation:
              frames: 4
              objects:
                crate:
                  keys:
                    - {frame: 0, rotate-y: 0}
                    - {frame: 4, rotate-y: 360}
            """);
        World world = s.load(1).world();
        Instance crate = (Instance) world.objects().get(1);
        // frame 1: a quarter turn after the translation to x = 1 takes the box's centre to z = -1
        Point3D centre = crate.boundingBox().center();
        assertEquals(0, centre.x(), 1e-9);
        assertEquals(-1, centre.z(), 1e-9);
        assertEquals(1, ((Instance) s.load(0).world().objects().get(1)).boundingBox().center().x(), 1e-12);
    }

    @Test
    void eachFrameIsAWorldOfItsOwnAndTheFramesShareTheirMeshes() throws Exception {
        Files.writeString(dir.resolve("tent.obj"), "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1 0\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
        Path file = Files.writeString(dir.resolve("m.yaml"), """
            image: {width: 16, height: 12, samples: 1}
            camera: {eye: [0, 3, 6], look-at: [0, 0.5, 0]}
            lights:
              - {type: point, position: [2, 6, 4], intensity: 60}
            objects:
              - {type: mesh, name: tent, file: tent.obj}
            animation:
              frames: 3
              camera: {orbit: {degrees: 90}}
              objects:
                tent: {keys: [{frame: 0, scale: 1}, {frame: 2, scale: [1, 2, 1]}]}
            """);
        SceneFile s = SceneFile.read(file, null);
        LoadedScene first = s.load(0);
        LoadedScene second = s.load(2);
        assertTrue(first.world() != second.world());
        assertNotEquals(first.world().camera(), second.world().camera());
        first.world().prepare();
        second.world().prepare();
        MeshBVH a = (MeshBVH) ((Instance) first.world().objects().get(0)).object();
        MeshBVH b = (MeshBVH) ((Instance) second.world().objects().get(0)).object();
        assertSame(a.mesh(), b.mesh(), "one parse and tree for every frame");
        assertTrue(first.report().statistics().stream().anyMatch(l -> l.contains("5 vertices")), first.report().statistics().toString());
        assertTrue(second.report().inputs().contains(dir.resolve("tent.obj").toAbsolutePath().normalize()),
                   "a later frame still names the mesh as an input: " + second.report().inputs());
        // frame 0 twice renders the same, whatever was loaded and prepared in between
        assertArrayEquals(pixels(s.load(0).world()), pixels(SceneFile.read(file, null).load(0).world()));
    }

    private static float[] pixels(World world) {
        world.prepare();
        Film film = new Film(16, 12);
        Renders.render(world, 1, 1, film);
        float[] p = new float[16 * 12 * 3];
        for (int y = 0, i = 0; y < 12; y++) {
            for (int x = 0; x < 16; x++) {
                for (int c = 0; c < 3; c++) {
                    p[i++] = film.get(x, y, c);
                }
            }
        }
        return p;
    }

    @Test
    void aWrongSectionIsOneMessageAtItsLine() throws Exception {
        assertMessage("""
            animation: {frames: 4, objects: {barrel: {keys: [{frame: 0, rotate-y: 0}]}}}
            """, "a.yaml:8:34: the animation moves object 'barrel', but no object has that name; named: crate");
        assertMessage("""
            animation: {fps: 4}
            """, "a.yaml:8:12: animation needs the key 'frames'");
        assertMessage("""
            animation: {frames: 4, camera: {keys: [{eye: [0, 1, 2]}]}}
            """, "a.yaml:8:40: camera key needs either 'frame'");
        assertMessage("""
            animation: {frames: 4, camera: {keys: [{frame: 2, fov: 30}, {frame: 1, fov: 20}]}}
            """, "a.yaml:8:69: keys must be in order of time");
        assertMessage("""
            animation: {frames: 4, camera: {interpolation: cubic, keys: [{frame: 2, fov: 30}]}}
            """, "unknown interpolation 'cubic'; allowed: linear, smooth");
        assertMessage("""
            animation: {frames: 4, camera: {keys: [{frame: 2, zoom: 3}]}}
            """, "unknown key 'zoom' in camera key; allowed: eye, fov, frame, look-at, time, up");
        SceneFile s = scene("""
            animation: {frames: 4, objects: {crate: {keys: [{frame: 0, scale: 1}, {frame: 2, scale: 0}]}}}
            """);
        s.load(0);
        SceneException e = assertThrows(SceneException.class, () -> s.load(2));
        assertTrue(e.getMessage().contains("a.yaml:8:34: the transform at frame 2 is singular"), e.getMessage());
        SceneFile fov = scene("""
            animation: {frames: 4, camera: {keys: [{frame: 0, fov: 40}, {frame: 3, fov: 180}]}}
            """);
        SceneException camera = assertThrows(SceneException.class, () -> fov.load(3));
        assertTrue(camera.getMessage().contains("a.yaml:8:32: field of view must be between 0 and 180 degrees, got 180.0 "
                                                + "(the camera at frame 3)"), camera.getMessage());
    }

    /**
     * Numbers past what a frame can use name their key and the range allowed, rather than turning
     * into an infinite frame or a camera whose eye is not a number: the orbit's sweep, a key's
     * frame or time (the frame number fits an int), and an orbit whose eye is turned past the
     * largest double.
     */
    @Test
    void hostileNumbersNameTheirKeyAndTheRangeAllowed() throws Exception {
        assertMessage("""
            animation: {frames: 4, camera: {orbit: {degrees: 1e308}}}
            """, "a.yaml:8:50: 'degrees' in orbit must be -360000000 to 360000000 (a turn a frame over 1000000 frames, the most "
                 + "an animation has), got 1.0E308");
        assertMessage("""
            animation: {frames: 4, camera: {keys: [{time: 0, fov: 30}, {time: 1e308, fov: 50}]}}
            """, "a.yaml:8:67: 'time' in camera key must be -89478485.29 to 89478485.29 seconds at 24 fps (frames "
                 + "-2147483647 to 2147483647), got 1.0E308");
        assertMessage("""
            animation: {frames: 4, fps: 1e6, objects: {crate: {keys: [{time: 1e4, scale: 2}]}}}
            """, "'time' in key of object 'crate' must be -2147.48 to 2147.48 seconds at 1000000 fps");
        assertMessage("""
            animation: {frames: 4, fps: 1e308}
            """, "a.yaml:8:29: 'fps' in animation must be 1.0E-6 to 1000000 (frames a second of the scene's time), got 1.0E308");
        assertMessage("""
            animation: {frames: 4, camera: {keys: [{frame: -1e308, fov: 30}, {frame: 1e308, fov: 50}]}}
            """, "a.yaml:8:48: 'frame' in camera key must be -2147483647 to 2147483647, got -1.0E308");
        SceneFile far = scene("""
            animation: {frames: 4, camera: {orbit: {center: [1e308, 0, 0]}}}
            """);
        far.load(0);
        SceneException e = assertThrows(SceneException.class, () -> far.load(2));
        assertTrue(e.getMessage().contains("a.yaml:8:49: the orbit turns the eye past the largest double at frame 2"), e.getMessage());
    }

    private void assertMessage(String animation, String expected) throws IOException {
        SceneException e = assertThrows(SceneException.class, () -> scene(animation));
        assertTrue(e.getMessage().startsWith(dir.resolve("a.yaml").toString()) && e.getMessage().contains(expected), e.getMessage());
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cache.MeshCache;

/**
 * Every file a scene reads besides the scene itself must be a regular file: a
 * FIFO would block the reader for ever without a word, a directory or device is no mesh or image.
 * The message says "not a regular file", not "not found". The FIFOs are made by this test.
 */
class NonRegularInputTest {
    @TempDir
    Path dir;

    private Path fifo(String name) throws IOException, InterruptedException {
        Path fifo = dir.resolve(name);
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        return fifo;
    }

    private Path scene(String objects, String materials) throws IOException {
        return Files.writeString(dir.resolve("s.yaml"), "image: {width: 4, height: 4, samples: 1}\n" + materials
                                                         + "objects:\n" + objects);
    }

    /** Loads (and prepares) the scene, which must fail at once naming the file as not a regular file. */
    private void assertRefused(Path scene, MeshCache cache, String file) {
        SceneException e = assertTimeoutPreemptively(Duration.ofSeconds(20), () -> assertThrows(SceneException.class, () -> {
            SceneLoader.load(scene, cache).world().prepare();
        }));
        assertTrue(e.getMessage().contains("not a regular file"), e.getMessage());
        assertTrue(e.getMessage().contains(file), e.getMessage());
    }

    @Test
    void aMeshThatIsAFifoIsRefusedAtOnceWithOrWithoutTheCache() throws Exception {
        fifo("m.obj");
        Path scene = scene("  - {type: mesh, file: m.obj}\n", "");
        assertRefused(scene, null, "m.obj");
        assertRefused(scene, MeshCache.in(dir.resolve("cache")), "m.obj");
        Files.createDirectory(dir.resolve("d.obj"));
        assertRefused(scene("  - {type: mesh, file: d.obj}\n", ""), null, "d.obj");
    }

    @Test
    void aMaterialLibraryThatIsAFifoIsAWarningAsAMissingOneIs() throws Exception {
        fifo("m.mtl");
        Files.writeString(dir.resolve("t.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        LoadedScene loaded = assertTimeoutPreemptively(Duration.ofSeconds(20),
                                                       () -> SceneLoader.load(scene("  - {type: mesh, file: t.obj}\n", ""), (MeshCache) null));
        assertTrue(loaded.report().warnings().toString().contains("m.mtl is not a regular file (it is a FIFO"),
                   loaded.report().warnings().toString());
    }

    @Test
    void imagesThatAreFifosAreRefused() throws Exception {
        fifo("wood.png");
        fifo("sky.hdr");
        assertRefused(scene("  - {type: sphere, center: [0, 0, 0], material: wood}\n",
                      "materials:\n  wood: {type: matte, texture: {type: image, file: wood.png}}\n"), null, "wood.png");
        Files.writeString(dir.resolve("s.yaml"), "environment: {file: sky.hdr}\nobjects:\n  - {type: sphere, center: [0, 0, 0]}\n");
        assertRefused(dir.resolve("s.yaml"), null, "sky.hdr");
    }
}

package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** --cache-dir keeps meshes between runs and --stats says which way each came; --no-cache keeps none. */
class MeshCacheOptionsTest {
    @TempDir
    Path dir;

    private Path scene() throws IOException {
        Files.writeString(dir.resolve("quad.obj"), "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 2 3 4\n");
        return Files.writeString(dir.resolve("s.yaml"), "image: {width: 8, height: 6, samples: 1}\n"
            + "camera: {eye: [0, 2, 3], look-at: [0, 0, 0], fov: 50}\n"
            + "lights:\n  - {type: point, position: [0, 2, 1], intensity: 5}\n"
            + "objects:\n  - {type: mesh, file: quad.obj}\n");
    }

    @Test
    void theSecondRunReadsTheCache() throws IOException {
        Path scene = scene();
        String cache = dir.resolve("meshes").toString();
        RenderCommandTest.Result first = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("1.pfm").toString(),
                                                               "--stats", "--cache-dir", cache);
        assertEquals(0, first.code(), first.err());
        assertTrue(first.err().contains("stats: mesh quad.obj: parsed in "), first.err());
        assertTrue(first.err().contains("written to the mesh cache in"), first.err());
        RenderCommandTest.Result second = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("2.pfm").toString(),
                                                                "--stats", "--cache-dir", cache);
        assertEquals(0, second.code(), second.err());
        assertTrue(second.err().matches("(?s).*stats: mesh quad\\.obj: read from the mesh cache in \\d+\\.\\d{3} s .*"), second.err());
        assertFalse(second.err().contains("parse quad.obj"), second.err());
        assertArrayEquals(Files.readAllBytes(dir.resolve("1.pfm")), Files.readAllBytes(dir.resolve("2.pfm")));
    }

    @Test
    void noCacheWritesNothingAndExcludesACacheFolder() throws IOException {
        Path scene = scene();
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("n.pfm").toString(), "--stats",
                                                           "--no-cache");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("stats: mesh quad.obj: parsed in ") && !r.err().contains("mesh cache"), r.err());
        RenderCommandTest.Result both = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("n.pfm").toString(),
                                                              "--no-cache", "--cache-dir", dir.toString());
        assertEquals(ErrorReport.BAD_USAGE, both.code());
        assertEquals("render: error: --no-cache and --cache-dir exclude each other (see render --help)", both.err().strip());
    }
}

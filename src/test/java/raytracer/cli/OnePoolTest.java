package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * One pool does all the parallel work of a run, sized by --threads: with one thread, the OBJ
 * parse, the parallel BVH build and every render of a --repeat start no thread but the pool's one
 * worker (the parser had a pool of its own, the builder used the common pool, and every render
 * made a new pool).
 */
class OnePoolTest {
    @TempDir
    Path dir;

    /** A triangle strip over {@code n} vertices: some 45 bytes a vertex, so 40,000 make two chunks. */
    private Path strip(int n) throws IOException {
        StringBuilder obj = new StringBuilder();
        for (int k = 0; k < n; k++) {
            obj.append("v ").append(k % 200 * 0.01).append(' ').append(k / 200 * 0.01).append(" 0\n");
            if (k >= 2) {
                obj.append("f ").append(k - 1).append(' ').append(k).append(' ').append(k + 1).append('\n');
            }
        }
        return Files.writeString(dir.resolve("strip.obj"), obj);
    }

    @Test
    void oneThreadMeansOneWorkerStartedForParseBuildAndRenders() throws IOException {
        Path mesh = strip(40_000); // 39,998 triangles: above the builders' parallel threshold (32,768)
        assertTrue(Files.size(mesh) > 1 << 20, "the parse runs as a pipeline of chunks");
        Path scene = Files.writeString(dir.resolve("s.yaml"), """
            image: {width: 8, height: 8, samples: 1}
            camera: {eye: [1, 1, 4], look-at: [1, 1, 0], fov: 40}
            lights:
              - {type: point, position: [1, 1, 3], intensity: 5}
            objects:
              - {type: mesh, file: strip.obj}
            """);
        long started = ManagementFactory.getThreadMXBean().getTotalStartedThreadCount();
        StringWriter err = new StringWriter();
        int code = RenderCommand.run(new PrintWriter(err, true), scene.toString(), "-o", dir.resolve("s.pfm").toString(),
                                     "--threads", "1", "--repeat", "2", "--stats", "--no-cache");
        long threads = ManagementFactory.getThreadMXBean().getTotalStartedThreadCount() - started;
        assertEquals(0, code, err.toString());
        assertTrue(err.toString().contains("sah BVH of strip.obj"), err.toString());
        assertEquals(1, threads, "threads started by the run");
    }
}

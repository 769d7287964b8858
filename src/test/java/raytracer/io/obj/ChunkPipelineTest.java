package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.shapes.mesh.Mesh;

/**
 * Files of several chunks ({@link LineChunks#CHUNK} bytes each) load as a serial read would load
 * them: the same arrays, and errors at the exact line, whichever chunk they fall in.
 */
class ChunkPipelineTest {
    /** Vertices of the strip: about 5 MB of text, five chunks. */
    private static final int N = 120_000;

    @TempDir
    Path dir;

    /** Vertex k (0-based) is (k, k / 2, -k / 4); after vertex k >= 2 comes "f k-1 k k+1", 1-based. */
    private static List<String> strip() {
        List<String> lines = new ArrayList<>();
        lines.add("# a triangle strip");
        for (int k = 0; k < N; k++) {
            lines.add("v " + k + " " + k / 2.0 + " " + -k / 4.0);
            if (k >= 2) {
                lines.add("f " + (k - 1) + " " + k + " " + (k + 1));
            }
        }
        return lines;
    }

    /** The line number (1-based) of vertex k's line in {@link #strip}. */
    private static int vertexLine(int k) {
        return 2 + k + Math.max(0, k - 2);
    }

    private Path write(String name, List<String> lines, String newline) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, String.join(newline, lines) + newline, StandardCharsets.UTF_8);
        assertTrue(Files.size(file) > 3 * LineChunks.CHUNK, "the file spans several chunks");
        return file;
    }

    private static void assertStrip(Mesh mesh) {
        assertEquals(N - 2, mesh.triangleCount());
        for (int k : new int[] {0, 1, 77_777, N - 1}) {
            assertArrayEquals(new double[] {k, k / 2.0, -k / 4.0},
                              Arrays.copyOfRange(mesh.positions(), 3 * k, 3 * k + 3), 0, "vertex " + k);
        }
        for (int t = 0; t < N - 2; t++) {
            assertEquals(t, mesh.vertex(t, 0));
            assertEquals(t + 1, mesh.vertex(t, 1));
            assertEquals(t + 2, mesh.vertex(t, 2));
        }
    }

    @Test
    void manyChunksWithAnyLineEnding() throws Exception {
        // chunks are cut after '\n', or after a '\r' not followed by '\n': the old-Mac CR-only file
        // is cut and parsed in parallel as the others are (it was one chunk, and 40 times slower)
        List<String> strip = strip();
        for (String newline : new String[] {"\n", "\r\n", "\r"}) {
            assertStrip(ObjLoader.load(write("strip.obj", strip, newline), false).mesh());
        }
    }

    @Test
    void chunksAreParsedInThePoolOfTheCaller() throws Exception {
        // run on the one thread of a pool of one, the pipeline leaves the chunks it has not merged
        // yet in that pool's queue; parsed anywhere else, the queue would stay empty
        Path file = write("strip.obj", strip(), "\n");
        ForkJoinPool one = new ForkJoinPool(1);
        try {
            List<Long> queued = new ArrayList<>();
            List<Thread> mergers = new ArrayList<>();
            Thread caller = one.submit(() -> {
                try (InputStream in = Files.newInputStream(file)) {
                    ChunkPipeline.run(new LineChunks(in), (text, chunk) -> {
                        queued.add(one.getQueuedTaskCount());
                        mergers.add(Thread.currentThread());
                    });
                }
                return Thread.currentThread();
            }).get();
            assertTrue(queued.size() >= 5, "chunks: " + queued.size());
            assertTrue(queued.stream().anyMatch(n -> n > 0), "parses waiting in the pool at each merge: " + queued);
            assertTrue(mergers.stream().allMatch(t -> t == caller), "merged on the caller's thread");
            assertEquals(1, one.getPoolSize(), "no thread was added to the pool");
        } finally {
            one.shutdown();
        }
    }

    @Test
    void continuedLinesStayTogether() throws Exception {
        List<String> lines = new ArrayList<>();
        for (String line : strip()) {
            // every vertex line cut in two, so some chunk boundary falls near a continuation
            lines.add(line.startsWith("v ") ? line.replaceFirst(" ", " \\\\\n") : line);
        }
        assertStrip(ObjLoader.load(write("continued.obj", lines, "\n"), false).mesh());
    }

    @Test
    void gzipOfManyChunks() throws Exception {
        Path gz = dir.resolve("strip.obj.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(gz))) {
            out.write((String.join("\n", strip()) + "\n").getBytes(StandardCharsets.UTF_8));
        }
        assertStrip(ObjLoader.load(gz, false).mesh());
        byte[] all = Files.readAllBytes(gz);
        Files.write(gz, Arrays.copyOf(all, 2 * all.length / 3));
        ObjException e = assertThrows(ObjException.class, () -> ObjLoader.load(gz, false));
        assertTrue(e.getMessage().contains("strip.obj.gz") && e.getMessage().contains("truncated"), e.getMessage());
    }

    @Test
    void indexOutOfRangeInALaterChunkNamesItsLine() throws IOException {
        List<String> lines = strip();
        int k = 100_000;
        int faceLine = vertexLine(k) + 1;
        lines.set(faceLine - 1, "f 1 2 " + (k + 2)); // the next vertex, not yet defined
        ObjException e = assertThrows(ObjException.class, () -> ObjLoader.load(write("bad.obj", lines, "\n"), false));
        assertEquals(dir.resolve("bad.obj") + ":" + faceLine + ": vertex index " + (k + 2) + " is out of range ("
                     + (k + 1) + " defined so far; indices are 1.." + (k + 1) + " or -1..-" + (k + 1) + ")", e.getMessage());
    }

    @Test
    void badNumberInALaterChunkNamesItsLine() throws IOException {
        List<String> lines = strip();
        int line = vertexLine(90_000);
        lines.set(line - 1, "v 1 2 nan");
        ObjException e = assertThrows(ObjException.class, () -> ObjLoader.load(write("bad.obj", lines, "\r\n"), false));
        assertTrue(e.getMessage().startsWith(dir.resolve("bad.obj") + ":" + line + ": coordinate 'nan'"), e.getMessage());
    }

    @Test
    void relativeIndicesAndMaterialsInALaterChunk() throws Exception {
        List<String> lines = strip();
        int k = 80_000;
        int faceLine = vertexLine(k) + 1;
        lines.set(faceLine - 1, "f -3 -2 -1"); // the same triangle, counted back from vertex k
        lines.add(faceLine - 1, "usemtl red");
        Mesh mesh = ObjLoader.load(write("relative.obj", lines, "\n"), false).mesh();
        assertStrip(mesh);
        int[] ids = mesh.materialIds();
        assertEquals(0, ids[0], "faces before the first usemtl have the fallback material");
        assertEquals(0, ids[k - 3]);
        assertEquals(1, ids[k - 2]);
        assertEquals(1, ids[N - 3]);
    }
}

package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A process stopped by SIGTERM or SIGINT while it writes an image leaves neither a partial file
 * beside the target nor a changed target. The writer is a real JVM ({@link WriterThatWaits}) that
 * says when it is inside the write and waits there, so the signal always lands mid-write.
 */
class InterruptedWriteTest {
    @TempDir
    Path dir;

    private static final byte[] GOOD = {1, 2, 3};

    /** Starts the writer on dir/out.png and returns once it is writing, with the partial file present. */
    private Process startWriting() throws IOException {
        Path target = dir.resolve("out.png");
        Files.write(target, GOOD);
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Process child = new ProcessBuilder(java.toString(), "-cp", System.getProperty("java.class.path"),
                                           WriterThatWaits.class.getName(), target.toString())
            .redirectErrorStream(true).start();
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8));
            assertEquals("writing", out.readLine(), "the writer did not start");
            assertEquals(1, partialFiles().size(), "the temporary file exists while the writer waits");
            return child;
        } catch (IOException | RuntimeException | Error e) {
            child.destroyForcibly();
            throw e;
        }
    }

    private List<Path> partialFiles() throws IOException {
        try (var files = Files.list(dir)) {
            return files.filter(p -> p.getFileName().toString().endsWith(".partial")).toList();
        }
    }

    private void assertCleanedUp(Process child) throws IOException, InterruptedException {
        boolean stopped = child.waitFor(20, TimeUnit.SECONDS);
        child.destroyForcibly();
        assertTrue(stopped, "the writer did not stop");
        assertEquals(List.of(), partialFiles(), "partial file left beside the target");
        assertArrayEquals(GOOD, Files.readAllBytes(dir.resolve("out.png")), "the old image must stay");
    }

    @Test
    void sigtermMidWriteRemovesThePartialFile() throws IOException, InterruptedException {
        Process child = startWriting();
        child.destroy(); // SIGTERM on POSIX systems
        assertCleanedUp(child);
    }

    @Test
    void sigintMidWriteRemovesThePartialFile() throws IOException, InterruptedException {
        Process child = startWriting();
        Process kill = new ProcessBuilder("kill", "-INT", Long.toString(child.pid())).start();
        assertEquals(0, kill.waitFor(), "kill -INT failed");
        assertCleanedUp(child);
    }
}

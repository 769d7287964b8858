package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a path names, from its mode bits; devices are only looked at. */
class FileKindTest {
    @TempDir
    Path dir;

    @Test
    void kindsOfFiles() throws IOException, InterruptedException {
        Path file = Files.writeString(dir.resolve("f"), "x");
        Path link = Files.createSymbolicLink(dir.resolve("l"), file);
        Path fifo = dir.resolve("p");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        assertEquals(FileKind.REGULAR, FileKind.of(file));
        assertEquals(FileKind.DIRECTORY, FileKind.of(dir));
        assertEquals(FileKind.REGULAR, FileKind.of(link));
        assertEquals(FileKind.SYMBOLIC_LINK, FileKind.ofLink(link));
        assertEquals(FileKind.FIFO, FileKind.of(fifo));
        assertEquals(FileKind.MISSING, FileKind.of(dir.resolve("none")));
        assertEquals(FileKind.CHARACTER_DEVICE, FileKind.of(Path.of("/dev/null")));
        assertTrue(FileKind.FIFO.writtenInPlace() && FileKind.CHARACTER_DEVICE.writtenInPlace());
        assertFalse(FileKind.BLOCK_DEVICE.writtenInPlace() || FileKind.REGULAR.writtenInPlace());
    }

    @Test
    void aChainOfLinksEndsAtItsTargetAndALoopIsRefused() throws IOException {
        Path target = dir.resolve("target.png");
        Path a = Files.createSymbolicLink(dir.resolve("a"), target.getFileName());
        Path b = Files.createSymbolicLink(dir.resolve("b"), a.getFileName());
        assertEquals(target, AtomicFile.destination(b), "a missing target is where the write goes");
        Path x = dir.resolve("x");
        Path y = dir.resolve("y");
        Files.createSymbolicLink(x, y.getFileName());
        Files.createSymbolicLink(y, x.getFileName());
        IOException e = assertThrows(IOException.class, () -> AtomicFile.destination(x));
        assertTrue(e.getMessage().contains("too many levels of symbolic links"), e.getMessage());
    }
}

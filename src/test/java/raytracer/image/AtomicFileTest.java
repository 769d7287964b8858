package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicFileTest {
    @TempDir
    Path dir;

    @Test
    void aWriteThatFailsHalfwayKeepsTheOldFileAndLeavesNoTemporary() throws IOException {
        Path target = dir.resolve("image.png");
        Files.write(target, new byte[] {9, 9});
        IOException e = assertThrows(IOException.class, () -> AtomicFile.write(target, out -> {
            out.write(new byte[] {1, 2, 3});
            throw new IOException("disk full");
        }));
        assertEquals("cannot write " + target + ": disk full", e.getMessage());
        assertArrayEquals(new byte[] {9, 9}, Files.readAllBytes(target));
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count());
        }
    }

    @Test
    void aFileSystemRefusalNamesTheTargetNotTheTemporary() {
        Path target = dir.resolve("gone/image.png");
        IOException e = assertThrows(IOException.class, () -> AtomicFile.write(target, out -> out.write(1)));
        assertEquals("cannot write " + target + ": no such file or directory", e.getMessage());
    }

    @Test
    void aSuccessfulWriteReplacesTheFile() throws IOException {
        Path target = dir.resolve("image.png");
        Files.write(target, new byte[] {9, 9});
        AtomicFile.write(target, out -> out.write(new byte[] {1, 2, 3}));
        assertArrayEquals(new byte[] {1, 2, 3}, Files.readAllBytes(target));
    }

    @Test
    void aNewFileGetsThePermissionsOfAPlainlyCreatedOneAndAReplacedFileKeepsItsOwn() throws IOException {
        assumeTrue(dir.getFileSystem().supportedFileAttributeViews().contains("posix"), "POSIX file system");
        Path plain = Files.createFile(dir.resolve("plain"));
        Path target = dir.resolve("new.png");
        AtomicFile.write(target, out -> out.write(1));
        assertEquals(Files.getPosixFilePermissions(plain), Files.getPosixFilePermissions(target));

        Path restricted = dir.resolve("restricted.png");
        Files.write(restricted, new byte[] {9});
        Set<PosixFilePermission> groupReadable = PosixFilePermissions.fromString("rw-r-----");
        Files.setPosixFilePermissions(restricted, groupReadable);
        AtomicFile.write(restricted, out -> out.write(2));
        assertEquals(groupReadable, Files.getPosixFilePermissions(restricted));
    }

    @Test
    void pfmRoundTripsLinearValues() throws IOException {
        Film film = new Film(3, 2);
        film.set(0, 0, 0.25, 12.5, 1e-6);
        film.set(2, 1, 100, 0, 3);
        Path file = dir.resolve("x.pfm");
        ImageWriters.write(film, 1, file);
        Film back = ImageWriters.readPfm(file);
        assertEquals(12.5f, back.get(0, 0, 1));
        assertEquals(1e-6f, back.get(0, 0, 2));
        assertEquals(100f, back.get(2, 1, 0));
        assertTrue(Files.size(file) > 3 * 2 * 12);
    }

    @Test
    void srgbEncodingMatchesTheStandardAtKnownPoints() {
        assertEquals(0, ToneMap.toByte(0, 1));
        assertEquals(255, ToneMap.toByte(1, 1));
        assertEquals(255, ToneMap.toByte(7, 1));
        assertEquals(0, ToneMap.toByte(Double.NaN, 1));
        // reference values of the IEC 61966-2-1 curve: linear 0.5 -> 0.7354 -> code 188; 0.18 -> 118
        assertEquals(0.5, ToneMap.srgbEncode(0.21404114), 1e-6);
        assertEquals(188, ToneMap.toByte(0.5, 1));
        assertEquals(118, ToneMap.toByte(0.18, 1));
        assertEquals(118, ToneMap.toByte(0.09, 2), "exposure multiplies before encoding");
        // the report's encoding: the clamped radiance is the code value
        assertEquals(128, ToneMap.toByte(0.5, 1, false));
        assertEquals(46, ToneMap.toByte(0.18, 1, false));
        assertEquals(255, ToneMap.toByte(3, 1, false));
        assertEquals(0, ToneMap.toByte(Double.NaN, 1, false));
        // the linear segment near black: 0.002 * 12.92 * 255 = 6.6
        assertEquals(7, ToneMap.toByte(0.002, 1));
    }
}

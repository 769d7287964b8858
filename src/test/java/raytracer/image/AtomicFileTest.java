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

    /**
     * A leftover is a temporary file of a write of the file named: beside the file written (a
     * link's target), named as the write names its temporary files; a temporary file a write makes
     * is one by that rule, and nothing else is removed.
     */
    @Test
    void leftoversAreTheTemporaryFilesOfTheFilesNamedAndNothingElse() throws IOException {
        Path frames = Files.createDirectories(dir.resolve("frames"));
        Path link = Files.createSymbolicLink(dir.resolve("a.png"), frames.resolve("b.png"));
        Path[] temporary = new Path[1];
        AtomicFile.write(link, out -> {
            try (var files = Files.list(frames)) {
                temporary[0] = files.filter(p -> !p.getFileName().toString().equals("b.png")).findFirst().orElseThrow();
            }
            out.write(1);
        });
        // the same name again, as a write killed before its rename leaves it
        Files.writeString(temporary[0], "left");
        Files.writeString(dir.resolve(".a.png.k3xq0.partial"), "beside the link, not the file written");
        Files.writeString(frames.resolve(".b.png.k3xq0.partial.old"), "another name");
        assertEquals(java.util.List.of(temporary[0]), AtomicFile.removeLeftovers(Set.of(link)));
        assertTrue(Files.exists(dir.resolve(".a.png.k3xq0.partial")));
        assertTrue(Files.exists(frames.resolve(".b.png.k3xq0.partial.old")));
        assertTrue(Files.exists(frames.resolve("b.png")));
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
        // 18 distinct values over 6 orders of magnitude, each exact in float, in every pixel and channel
        Film film = new Film(3, 2);
        float[] values = new float[18];
        for (int i = 0; i < 18; i++) {
            values[i] = (float) ((i + 1) * Math.pow(10, i % 6 - 3));
        }
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                int i = 3 * (y * 3 + x);
                film.set(x, y, values[i], values[i + 1], values[i + 2]);
            }
        }
        Path file = dir.resolve("x.pfm");
        ImageWriters.write(film, 1, file);
        Film back = ImageWriters.readPfm(file);
        assertEquals(3, back.width());
        assertEquals(2, back.height());
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(values[3 * (y * 3 + x) + c], back.get(x, y, c), 0, "pixel " + x + ", " + y + ", channel " + c);
                }
            }
        }
        // header "PF\n3 2\n-1.0\n" (12 bytes), then little-endian floats with the bottom row first
        byte[] bytes = Files.readAllBytes(file);
        assertEquals("PF\n3 2\n-1.0\n", new String(bytes, 0, 12, java.nio.charset.StandardCharsets.US_ASCII));
        assertEquals(12 + 18 * 4, bytes.length);
        java.nio.ByteBuffer data = java.nio.ByteBuffer.wrap(bytes, 12, 72).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        assertEquals(values[9], data.getFloat(), 0, "pixel (0, 1), red, comes first");
        assertEquals(values[10], data.getFloat(), 0);
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

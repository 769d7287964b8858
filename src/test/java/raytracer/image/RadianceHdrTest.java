package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.io.obj.TestAssets;

class RadianceHdrTest {
    @TempDir
    Path dir;

    private static byte[] header(String extra, int w, int h) {
        return ("#?RADIANCE\n" + extra + "FORMAT=32-bit_rle_rgbe\n\n-Y " + h + " +X " + w + "\n").getBytes(StandardCharsets.US_ASCII);
    }

    @Test
    void flatAndRunLengthScanlinesDecodeExactly() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int w = 8;
        out.writeBytes(header("# a comment\nGAMMA=1\nPRIMARIES=0 0 0 0 0 0 0 0\n", w, 2));
        // row 0, new-style RLE: r is a run of 8 x 128, g literals 0..7, b a run of 0, e a run of 129 (2^1)
        out.writeBytes(new byte[] {2, 2, 0, (byte) w});
        out.writeBytes(new byte[] {(byte) (128 + 8), (byte) 128});
        out.write(8);
        for (int i = 0; i < 8; i++) {
            out.write(i * 32);
        }
        out.writeBytes(new byte[] {(byte) (128 + 8), 0});
        out.writeBytes(new byte[] {(byte) (128 + 8), (byte) 129});
        // row 1, flat: (64, 0, 0, 128) then zeros (e = 0 is black)
        for (int x = 0; x < w; x++) {
            out.writeBytes(x == 0 ? new byte[] {64, 0, 0, (byte) 128} : new byte[] {10, 10, 10, 0});
        }
        Path file = dir.resolve("t.hdr");
        Files.write(file, out.toByteArray());
        Film film = RadianceHdr.read(file);
        assertEquals(8, film.width());
        assertEquals(2, film.height());
        // (m + 0.5) / 256 * 2^(e - 128)
        assertEquals((128 + 0.5) / 256 * 2, film.get(3, 0, 0), 1e-7);
        assertEquals((5 * 32 + 0.5) / 256 * 2, film.get(5, 0, 1), 1e-7);
        assertEquals((0.5) / 256 * 2, film.get(0, 0, 2), 1e-7);
        assertEquals((64 + 0.5) / 256, film.get(0, 1, 0), 1e-7);
        assertEquals(0, film.get(1, 1, 0), 0);
    }

    @Test
    void truncatedFilesNameThemselves() throws IOException {
        Path source = TestAssets.path("env/venice_sunset_1k.hdr");
        byte[] all = Files.readAllBytes(source);
        Path cut = dir.resolve("cut.hdr");
        Files.write(cut, Arrays.copyOf(all, all.length / 3));
        IOException e = assertThrows(IOException.class, () -> RadianceHdr.read(cut));
        assertTrue(e.getMessage().contains("cut.hdr"), e.getMessage());
        Path text = Files.writeString(dir.resolve("no.hdr"), "hello\n");
        assertTrue(assertThrows(IOException.class, () -> RadianceHdr.read(text)).getMessage().contains("not a Radiance"));
    }

    @Test
    void environmentMapsWithExtraHeaderLines() throws IOException {
        String[] names = {"venice_sunset_1k.hdr", "quarry_01_1k.hdr", "royal_esplanade_1k.hdr"};
        double[] peaks = {44, 64_000, 41_000};
        for (int i = 0; i < names.length; i++) {
            Film film = ImageFiles.read(TestAssets.path("env/" + names[i]));
            assertEquals(1024, film.width());
            assertEquals(512, film.height());
            double peak = 0;
            for (int y = 0; y < 512; y++) {
                for (int x = 0; x < 1024; x++) {
                    peak = Math.max(peak, 0.2126 * film.get(x, y, 0) + 0.7152 * film.get(x, y, 1) + 0.0722 * film.get(x, y, 2));
                }
            }
            assertEquals(peaks[i], peak, 0.01 * peaks[i], names[i]);
        }
    }
}

package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading PFM files: both byte orders, rows from the bottom, and one clear message for a bad file. */
class PfmReadTest {
    @TempDir
    Path dir;

    private Path file(String name, byte[] bytes) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, bytes);
        return p;
    }

    /** A 2x2 colour PFM in the given byte order whose value at (x, y, c) is 100 y + 10 x + c. */
    private static byte[] pfm(ByteOrder order) {
        byte[] header = ("PF\n2 2\n" + (order == ByteOrder.LITTLE_ENDIAN ? "-1.0" : "1.0") + "\n")
            .getBytes(StandardCharsets.US_ASCII);
        ByteBuffer data = ByteBuffer.allocate(header.length + 48).order(order);
        data.put(header);
        for (int y = 1; y >= 0; y--) { // rows from the bottom
            for (int x = 0; x < 2; x++) {
                for (int c = 0; c < 3; c++) {
                    data.putFloat(100 * y + 10 * x + c);
                }
            }
        }
        return data.array();
    }

    @Test
    void bothByteOrdersReadWithTheTopRowFirst() throws IOException {
        for (ByteOrder order : new ByteOrder[] {ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN}) {
            Film film = ImageWriters.readPfm(file("a.pfm", pfm(order)));
            assertEquals(2, film.width());
            assertEquals(112, film.get(1, 1, 2), 0, order.toString());
            assertEquals(10, film.get(1, 0, 0), 0, order.toString());
        }
    }

    private void assertRefused(byte[] bytes, String fragment) throws IOException {
        Path p = file("bad.pfm", bytes);
        IOException e = assertThrows(IOException.class, () -> ImageWriters.readPfm(p));
        assertTrue(e.getMessage().startsWith(p.toString()) && e.getMessage().contains(fragment), e.getMessage());
    }

    @Test
    void badFilesAreOneClearMessage() throws IOException {
        assertRefused("\u0089PNG\r\n\u001a\n".getBytes(StandardCharsets.ISO_8859_1), "not a PFM image");
        assertRefused(new byte[0], "not a PFM image");
        assertRefused("Pf\n2 2\n-1\n".getBytes(StandardCharsets.US_ASCII), "greyscale");
        assertRefused("PF\ntwo 2\n-1\n".getBytes(StandardCharsets.US_ASCII), "bad PFM header");
        assertRefused("PF\n2".getBytes(StandardCharsets.US_ASCII), "bad PFM header");
        assertRefused("PF\n0 2\n-1\n".getBytes(StandardCharsets.US_ASCII), "bad PFM header");
        byte[] whole = pfm(ByteOrder.LITTLE_ENDIAN);
        assertRefused(java.util.Arrays.copyOf(whole, whole.length - 5), "truncated PFM: 43 bytes of pixels, 48 expected");
    }
}

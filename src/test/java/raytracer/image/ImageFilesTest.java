package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.CRC32;
import javax.imageio.IIOException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Texture images that cannot be read: each message names the file and says what is wrong with it. */
class ImageFilesTest {
    @TempDir
    Path dir;

    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

    private String error(Path file) {
        return assertThrows(IOException.class, () -> ImageFiles.read(file)).getMessage();
    }

    /** A PNG chunk: length, type, data, CRC of type and data (PNG specification, section 5.3). */
    private static void chunk(DataOutputStream out, String type, byte[] data) throws IOException {
        out.writeInt(data.length);
        byte[] name = type.getBytes(StandardCharsets.US_ASCII);
        out.write(name);
        out.write(data);
        CRC32 crc = new CRC32();
        crc.update(name);
        crc.update(data);
        out.writeInt((int) crc.getValue());
    }

    /** The signature and an IHDR for an 8-bit RGB image of w x h, and no pixel data. */
    private static byte[] pngHeader(int w, int h) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.write(PNG_SIGNATURE);
        ByteArrayOutputStream ihdr = new ByteArrayOutputStream();
        DataOutputStream header = new DataOutputStream(ihdr);
        header.writeInt(w);
        header.writeInt(h);
        header.write(new byte[] {8, 2, 0, 0, 0}); // depth 8, colour type RGB, deflate, filter 0, no interlace
        chunk(out, "IHDR", ihdr.toByteArray());
        return bytes.toByteArray();
    }

    @Test
    void aBrokenPngNamesItsFile() throws IOException {
        // a PNG signature followed by garbage: ImageIO said only "I/O error reading PNG header!"
        Path file = Files.write(dir.resolve("broken.png"), java.util.Arrays.copyOf(PNG_SIGNATURE, 40));
        assertEquals("cannot read image " + file + ": I/O error reading PNG header!", error(file));
    }

    /**
     * A JPEG cut short was accepted, its missing part filled with grey (a PNG cut
     * short is refused); the decoder's warning now refuses it too. Made here from a small JPEG.
     */
    @Test
    void aTruncatedJpegIsRefused() throws IOException {
        java.awt.image.BufferedImage image = new java.awt.image.BufferedImage(256, 256, java.awt.image.BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 256; y++) {
            for (int x = 0; x < 256; x++) {
                image.setRGB(x, y, x << 16 | y << 8 | (x * 7 ^ y * 13) & 0xff);
            }
        }
        ByteArrayOutputStream jpeg = new ByteArrayOutputStream();
        javax.imageio.ImageIO.write(image, "jpg", jpeg);
        Path whole = Files.write(dir.resolve("whole.jpg"), jpeg.toByteArray());
        assertEquals(256, ImageFiles.read(whole).width(), "the whole file reads");
        Path cut = Files.write(dir.resolve("cut.jpg"), java.util.Arrays.copyOf(jpeg.toByteArray(), jpeg.size() / 2));
        String error = error(cut);
        assertTrue(error.startsWith("cannot read image " + cut + ": it is damaged or cut short ("), error);
    }

    @Test
    void aFileOfNoImageFormatNamesItsFile() throws IOException {
        Path file = Files.writeString(dir.resolve("text.png"), "not an image at all");
        assertEquals("image " + file + " is not a PNG, JPEG or other format ImageIO reads", error(file));
    }

    @Test
    void aDirectoryIsCalledADirectory() throws IOException {
        // it was "not found"
        Path folder = Files.createDirectory(dir.resolve("folder.png"));
        assertEquals("image " + folder + " is not a regular file (it is a directory)", error(folder));
        assertEquals("image " + dir.resolve("none.png") + " not found", error(dir.resolve("none.png")));
    }

    @Test
    void anImageTooLargeForTheHeapIsRefusedFromItsHeader() throws IOException {
        // 20000 x 20000 under a small heap gave "Caught exception during read: " and nothing more
        long need = 20_000L * 20_000 * ImageFiles.BYTES_PER_PIXEL / (1024 * 1024);
        assumeTrue(need > Runtime.getRuntime().maxMemory() / (1024 * 1024), "the test runs with less heap than that");
        Path png = Files.write(dir.resolve("huge.png"), pngHeader(20_000, 20_000));
        assertEquals("image " + png + " is 20000 x 20000 pixels and needs about " + need + " MiB to read, more than "
                     + "Java's heap (at most " + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB); give Java more "
                     + "heap, e.g. java -Xmx8g -jar render.jar ...", error(png));
        Path hdr = Files.write(dir.resolve("huge.hdr"),
            "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 20000 +X 20000\n".getBytes(StandardCharsets.US_ASCII));
        assertTrue(error(hdr).startsWith("image " + hdr + " is 20000 x 20000 pixels and needs about "), error(hdr));
    }

    @Test
    void sizesNoFilmHoldsAreRefused() throws IOException {
        Path empty = Files.write(dir.resolve("empty.hdr"), "#?RADIANCE\n\n-Y 0 +X 5\n".getBytes(StandardCharsets.US_ASCII));
        assertEquals("image " + empty + " is 5 x 0 pixels; an image holds 1 to 715827879", error(empty));
        Path wide = Files.write(dir.resolve("wide.png"), pngHeader(40_000, 40_000));
        assertEquals("image " + wide + " is 40000 x 40000 pixels; an image holds 1 to 715827879", error(wide));
        Path digits = Files.write(dir.resolve("digits.hdr"), "#?RADIANCE\n\n-Y 99999999999 +X 5\n".getBytes(StandardCharsets.US_ASCII));
        assertEquals(digits + ": image size 99999999999 is too large", error(digits));
    }

    @Test
    void aReaderFailureWithAnEmptyReasonGetsItsCause() {
        IOException wrapped = new IIOException("Caught exception during read: ", new OutOfMemoryError("Java heap space"));
        assertEquals("Caught exception during read: out of memory (Java heap space); give Java more heap, e.g. "
                     + "java -Xmx8g -jar render.jar ...", ImageFiles.reason(wrapped));
        IOException other = new IIOException("Caught exception during read: ", new ArrayIndexOutOfBoundsException());
        assertEquals("Caught exception during read: ArrayIndexOutOfBoundsException", ImageFiles.reason(other));
        assertEquals("I/O error reading PNG header!", ImageFiles.reason(new IIOException("I/O error reading PNG header!")));
    }
}

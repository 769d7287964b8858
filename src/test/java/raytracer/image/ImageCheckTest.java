package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.zip.CRC32;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A whole image passes and nothing else does: every byte of a PNG and of a PFM flipped, every
 * length cut short, bytes added after the end, a value that is not finite, another size. PNGs
 * that other programs write (interlaced, 16-bit, grey, palette) are whole too.
 */
class ImageCheckTest {
    @TempDir
    Path dir;

    private static Film film(int w, int h) {
        Film film = new Film(w, h);
        SplittableRandom random = new SplittableRandom(w * 7L + h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                film.set(x, y, random.nextDouble(), random.nextDouble(), random.nextDouble());
            }
        }
        return film;
    }

    private String check(String name, byte[] bytes, int w, int h) throws IOException {
        Path file = Files.write(dir.resolve(name), bytes);
        return ImageCheck.whyNotWhole(file, w, h);
    }

    @Test
    void aWrittenPngIsWholeAndEveryFlippedByteOrCutIsFound() throws IOException {
        Path file = dir.resolve("f.png");
        ImageWriters.write(film(7, 5), 1, file);
        byte[] good = Files.readAllBytes(file);
        assertNull(ImageCheck.whyNotWhole(file, 7, 5));
        assertEquals("is 7x5, not 8x5", ImageCheck.whyNotWhole(file, 8, 5));
        for (int i = 0; i < good.length; i++) {
            byte[] flipped = good.clone();
            flipped[i] ^= 0x01;
            assertNotNull(check("x.png", flipped, 7, 5), "byte " + i + " flipped");
        }
        for (int n = 0; n < good.length; n++) {
            assertNotNull(check("x.png", Arrays.copyOf(good, n), 7, 5), "cut to " + n + " bytes");
        }
        assertEquals("is empty", check("x.png", new byte[0], 7, 5));
        assertEquals("is damaged (1 byte follows its IEND chunk)", check("x.png", Arrays.copyOf(good, good.length + 1), 7, 5));
        assertEquals("is cut short (in chunk IEND)", check("x.png", Arrays.copyOf(good, good.length - 1), 7, 5));
    }

    /** A flipped byte of pixel data whose chunk's CRC was made again: only decompressing finds it. */
    @Test
    void pixelDataThatDoNotDecompressAreFoundBehindARightCrc() throws IOException {
        Path file = dir.resolve("f.png");
        ImageWriters.write(film(40, 30), 1, file);
        byte[] bytes = Files.readAllBytes(file);
        int idat = indexOf(bytes, "IDAT");
        int length = ByteBuffer.wrap(bytes, idat - 4, 4).getInt();
        bytes[idat + 4 + length - 2] ^= 0x40; // in the Adler-32 at the end of the zlib stream
        CRC32 crc = new CRC32();
        crc.update(bytes, idat, 4 + length);
        ByteBuffer.wrap(bytes, idat + 4 + length, 4).putInt((int) crc.getValue());
        String why = check("x.png", bytes, 40, 30);
        assertTrue(why.startsWith("is damaged (its pixel data do not decompress"), why);
    }

    @Test
    void pngsThatOtherProgramsWriteAreWhole() throws IOException {
        BufferedImage[] images = {new BufferedImage(13, 11, BufferedImage.TYPE_INT_RGB),
                                  new BufferedImage(13, 11, BufferedImage.TYPE_USHORT_GRAY),
                                  new BufferedImage(13, 11, BufferedImage.TYPE_BYTE_BINARY),
                                  new BufferedImage(13, 11, BufferedImage.TYPE_INT_ARGB)};
        for (int k = 0; k < images.length; k++) {
            BufferedImage image = images[k];
            for (int y = 0; y < 11; y++) {
                for (int x = 0; x < 13; x++) {
                    image.setRGB(x, y, 0xff000000 | (x * 19 + y * 7) * 0x10305);
                }
            }
            for (boolean interlaced : new boolean[] {false, true}) {
                Path file = dir.resolve(k + "-" + interlaced + ".png");
                write(image, file, interlaced);
                assertNull(ImageCheck.whyNotWhole(file, 13, 11), file.getFileName() + " " + image.getType());
                byte[] cut = Files.readAllBytes(file);
                // IHDR's last byte, after the signature, its length and type, and 12 bytes of it
                assertEquals(interlaced ? 1 : 0, cut[8 + 8 + 12], "Adam7 or not");
                assertNotNull(check("cut.png", Arrays.copyOf(cut, cut.length - 13), 13, 11));
            }
        }
    }

    private static void write(BufferedImage image, Path file, boolean interlaced) throws IOException {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setProgressiveMode(interlaced ? ImageWriteParam.MODE_DEFAULT : ImageWriteParam.MODE_DISABLED);
        try (ImageOutputStream out = ImageIO.createImageOutputStream(file.toFile())) {
            writer.setOutput(out);
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
    }

    @Test
    void aWrittenPfmIsWholeAndEveryCutOrNonFiniteValueIsFound() throws IOException {
        Path file = dir.resolve("f.pfm");
        ImageWriters.write(film(3, 2), 1, file);
        byte[] good = Files.readAllBytes(file);
        assertNull(ImageCheck.whyNotWhole(file, 3, 2));
        assertEquals("is 3x2, not 2x3", ImageCheck.whyNotWhole(file, 2, 3));
        for (int n = 0; n < good.length; n++) {
            assertNotNull(check("x.pfm", Arrays.copyOf(good, n), 3, 2), "cut to " + n + " bytes");
        }
        assertEquals("is damaged (4 bytes follow its pixels)", check("x.pfm", Arrays.copyOf(good, good.length + 4), 3, 2));
        byte[] infinite = good.clone();
        // the first pixel stored is the bottom row's first: (0, 1)
        int pixels = good.length - 12 * 6;
        ByteBuffer.wrap(infinite).order(ByteOrder.LITTLE_ENDIAN).putFloat(pixels + 12 + 8, Float.POSITIVE_INFINITY);
        assertEquals("is damaged (pixel (1, 1) is not a finite number)", check("x.pfm", infinite, 3, 2));
        assertEquals("is not a colour PFM file (it does not start with 'PF')",
                     check("x.pfm", "Pf\n3 2\n-1\n".getBytes(StandardCharsets.US_ASCII), 3, 2));
        assertEquals("is cut short (0 bytes of pixels, 72 expected for 3x2)",
                     check("x.pfm", "PF\n3 2\n-1.0\n".getBytes(StandardCharsets.US_ASCII), 3, 2));
    }

    @Test
    void aFileThatCannotBeReadSaysWhy() throws IOException {
        String why = ImageCheck.whyNotWhole(dir.resolve("none.png"), 1, 1);
        assertTrue(why.startsWith("cannot be read (no such file"), why);
    }

    private static int indexOf(byte[] bytes, String part) {
        byte[] p = part.getBytes(StandardCharsets.US_ASCII);
        for (int i = 0; i + p.length <= bytes.length; i++) {
            if (Arrays.equals(bytes, i, i + p.length, p, 0, p.length)) {
                return i;
            }
        }
        throw new AssertionError(part + " not found");
    }
}

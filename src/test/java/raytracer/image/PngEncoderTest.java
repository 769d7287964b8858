package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.SplittableRandom;
import java.util.zip.CRC32;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/** The PNG writer's files: ImageIO reads back every code, and every chunk's CRC is right. */
class PngEncoderTest {

    /** Random codes (the Sub filter's wrap-around included) over several IDAT chunks, and a 1x1 image. */
    @Test
    void imageIoReadsBackEveryCode() throws IOException {
        for (int[] size : new int[][] {{1, 1}, {7, 3}, {300, 200}}) {
            int w = size[0];
            int h = size[1];
            byte[] codes = new byte[3 * w * h];
            new SplittableRandom(w * 31L + h).nextBytes(codes);
            byte[] png = encode(w, h, codes);
            BufferedImage image = ImageIO.read(new ByteArrayInputStream(png));
            assertEquals(w, image.getWidth());
            assertEquals(h, image.getHeight());
            byte[] read = new byte[codes.length];
            for (int y = 0, i = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int rgb = image.getRGB(x, y);
                    read[i++] = (byte) (rgb >> 16);
                    read[i++] = (byte) (rgb >> 8);
                    read[i++] = (byte) rgb;
                }
            }
            assertArrayEquals(codes, read, w + "x" + h);
        }
    }

    /** Chunks in order IHDR, IDAT..., IEND, each with the CRC of its type and data (PNG section 5.3). */
    @Test
    void everyChunkCarriesTheCrcOfItsTypeAndData() throws IOException {
        byte[] codes = new byte[3 * 300 * 300];
        new SplittableRandom(7).nextBytes(codes); // incompressible: more than one IDAT chunk
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(encode(300, 300, codes)));
        in.skipNBytes(8);
        StringBuilder types = new StringBuilder();
        String type;
        do {
            int length = in.readInt();
            byte[] name = in.readNBytes(4);
            byte[] data = in.readNBytes(length);
            CRC32 crc = new CRC32();
            crc.update(name);
            crc.update(data);
            type = new String(name, StandardCharsets.US_ASCII);
            assertEquals((int) crc.getValue(), in.readInt(), "CRC of " + type);
            types.append(type).append(' ');
        } while (!type.equals("IEND"));
        assertEquals(0, in.available(), "nothing after IEND");
        String order = types.toString().trim();
        assertTrue(order.matches("IHDR( IDAT){2,} IEND"), order);
    }

    private static byte[] encode(int w, int h, byte[] codes) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.write(w, h, (y, rgb) -> System.arraycopy(codes, 3 * w * y, rgb, 0, 3 * w), out);
        return out.toByteArray();
    }
}

package raytracer.image;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Whether a stream is a whole colour PFM of a given size, as {@link ImageWriters} writes it, read
 * to its end in constant memory: the header ("PF", width, height, scale, one whitespace byte),
 * exactly 12 bytes a pixel after it, and every value finite (the writer writes no other). The
 * reasons complete a sentence that starts with the file's name.
 */
final class PfmCheck {
    private PfmCheck() {
    }

    /** Why {@code in} (buffered: the header is read a byte at a time) is not a whole PFM of {@code width} x {@code height}, or null. */
    static String whyNotWhole(InputStream in, int width, int height) throws IOException {
        String magic = token(in);
        if (magic.isEmpty()) {
            return "is empty";
        }
        if (!magic.equals("PF")) {
            return "is not a colour PFM file (it does not start with 'PF')";
        }
        String[] fields = {token(in), token(in), token(in)};
        long w;
        long h;
        double scale;
        try {
            w = Long.parseLong(fields[0]);
            h = Long.parseLong(fields[1]);
            scale = Double.parseDouble(fields[2]);
        } catch (NumberFormatException e) {
            return fields[2].isEmpty() ? "is cut short (in its header)"
                : "is damaged (its header is not 'PF', a width, a height and a scale)";
        }
        if (scale == 0 || !Double.isFinite(scale)) {
            return "is damaged (its header's scale is " + fields[2] + ")";
        }
        if (w != width || h != height) {
            return "is " + w + "x" + h + ", not " + width + "x" + height;
        }
        return pixels(in, width, height, scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
    }

    /** The pixels after the header's scale and its one whitespace byte: all there, all finite, and nothing after them. */
    private static String pixels(InputStream in, int width, int height, ByteOrder order) throws IOException {
        long expected = 12L * width * height;
        byte[] buffer = new byte[12 * 4096];
        long read = 0;
        for (int n; (n = in.readNBytes(buffer, 0, buffer.length)) > 0; ) {
            ByteBuffer values = ByteBuffer.wrap(buffer, 0, (int) Math.max(0, Math.min(n, expected - read))).order(order);
            for (int i = 0; values.remaining() >= 4; i += 4) {
                if (!Float.isFinite(values.getFloat())) {
                    long pixel = (read + i) / 12;
                    return "is damaged (pixel (" + pixel % width + ", " + (height - 1 - pixel / width) + ") is not a finite number)";
                }
            }
            read += n;
        }
        if (read < expected) {
            return "is cut short (" + read + " bytes of pixels, " + expected + " expected for " + width + "x" + height + ")";
        }
        return read == expected ? null : "is damaged (" + (read - expected) + " bytes follow its pixels)";
    }

    /**
     * The next word of the header; the one whitespace byte after it is read too, so that after the
     * scale the stream is at the first pixel. Empty at the end of the stream.
     */
    private static String token(InputStream in) throws IOException {
        StringBuilder word = new StringBuilder();
        int b = in.read();
        while (b >= 0 && Character.isWhitespace(b) && word.length() == 0) {
            b = in.read();
        }
        while (b >= 0 && !Character.isWhitespace(b) && word.length() < 32) {
            word.append((char) b);
            b = in.read();
        }
        return word.toString();
    }
}

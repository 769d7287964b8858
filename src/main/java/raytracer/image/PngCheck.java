package raytracer.image;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

/**
 * Whether a stream is a whole PNG image of a given size, read to its end in constant memory:
 * the signature; every chunk's CRC (PNG, ISO/IEC 15948, section 5.3); IHDR first, its size the one
 * asked; the IDAT chunks one after another, their zlib stream decompressed to its end (the
 * Inflater checks its Adler-32) into exactly the scanlines the header makes (section 7.2, with
 * Adam7's passes when interlaced, 8.2), each starting with a filter type of 0 to 4 (9.2); IEND
 * last, with nothing after it. The reasons complete a sentence that starts with the file's name.
 */
final class PngCheck {
    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    /** Adam7's passes (section 8.2): first column, first row, column step, row step. */
    private static final int[][] ADAM7 = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};

    private final DataInputStream in;
    private final byte[] buffer = new byte[1 << 16];
    private final byte[] pixels = new byte[1 << 16];
    private final CRC32 crc = new CRC32();
    private final Inflater inflater = new Inflater();
    /** The scanlines the header makes: per pass, rows and bytes a row (its filter type byte included). */
    private long[] rows;
    private long[] rowBytes;
    private int pass;
    private long row;
    private long inRow;
    private long decompressed;
    private long expected;

    private PngCheck(InputStream in) {
        this.in = new DataInputStream(in);
    }

    /** Why {@code in} is not a whole PNG of {@code width} x {@code height} pixels, or null when it is one. */
    static String whyNotWhole(InputStream in, int width, int height) throws IOException {
        PngCheck check = new PngCheck(in);
        try {
            return check.check(width, height);
        } finally {
            check.inflater.end();
        }
    }

    private String check(int width, int height) throws IOException {
        byte[] signature = new byte[SIGNATURE.length];
        int n = in.readNBytes(signature, 0, signature.length);
        if (n == 0) {
            return "is empty";
        }
        if (n < signature.length || !java.util.Arrays.equals(signature, SIGNATURE)) {
            return "is not a PNG file (it does not start with PNG's signature)";
        }
        boolean seenHeader = false;
        boolean idat = false;
        boolean afterIdat = false;
        while (true) {
            byte[] type = new byte[4];
            long length;
            try {
                length = Integer.toUnsignedLong(in.readInt());
                in.readFully(type);
            } catch (EOFException e) {
                return "is cut short (it ends before its IEND chunk)";
            }
            String name = new String(type, StandardCharsets.ISO_8859_1);
            if (length > Integer.MAX_VALUE) {
                return "is damaged (chunk " + name + " claims " + length + " bytes; at most " + Integer.MAX_VALUE + " are allowed)";
            }
            if (!seenHeader && !name.equals("IHDR")) {
                return "is damaged (its first chunk is " + name + ", not IHDR)";
            }
            if (name.equals("IDAT") && afterIdat) {
                return "is damaged (its IDAT chunks are not one after another)";
            }
            afterIdat |= idat && !name.equals("IDAT");
            crc.reset();
            crc.update(type);
            byte[] ihdr = name.equals("IHDR") ? new byte[13] : null;
            String why;
            try {
                why = data(name, length, ihdr);
            } catch (EOFException e) {
                return "is cut short (in chunk " + name + ")";
            }
            long stored;
            try {
                stored = Integer.toUnsignedLong(in.readInt());
            } catch (EOFException e) {
                return "is cut short (in chunk " + name + ")";
            }
            if (stored != crc.getValue()) {
                return "is damaged (chunk " + name + "'s CRC does not match)";
            }
            if (why != null) {
                return why;
            }
            if (ihdr != null) {
                if (seenHeader) {
                    return "is damaged (it has two IHDR chunks)";
                }
                seenHeader = true;
                why = header(ihdr, length, width, height);
                if (why != null) {
                    return why;
                }
            }
            idat |= name.equals("IDAT");
            if (name.equals("IEND")) {
                return end(idat);
            }
        }
    }

    /**
     * Reads a chunk's data into the CRC (and {@code ihdr}, or the Inflater for IDAT); why its pixel
     * data are wrong, or null. Read to its end even then: a CRC that does not match says more.
     */
    private String data(String name, long length, byte[] ihdr) throws IOException {
        String why = null;
        long left = length;
        while (left > 0) {
            int n = in.read(buffer, 0, (int) Math.min(buffer.length, left));
            if (n < 0) {
                throw new EOFException();
            }
            crc.update(buffer, 0, n);
            long at = length - left;
            if (ihdr != null && at < ihdr.length) {
                System.arraycopy(buffer, 0, ihdr, (int) at, (int) Math.min(n, ihdr.length - at));
            }
            if (name.equals("IDAT") && rows != null && why == null) {
                why = inflate(n);
            }
            left -= n;
        }
        return why;
    }

    /** The header: its size the one asked, a bit depth its colour type allows; sets up the scanlines it makes. */
    private String header(byte[] ihdr, long length, int width, int height) {
        ByteBuffer h = ByteBuffer.wrap(ihdr);
        long w = Integer.toUnsignedLong(h.getInt());
        long ht = Integer.toUnsignedLong(h.getInt());
        int depth = h.get() & 0xff;
        int colour = h.get() & 0xff;
        int compression = h.get() & 0xff;
        int filter = h.get() & 0xff;
        int interlace = h.get() & 0xff;
        if (length != 13) {
            return "is damaged (its IHDR chunk holds " + length + " bytes, not 13)";
        }
        if (w != width || ht != height) {
            return "is " + w + "x" + ht + ", not " + width + "x" + height;
        }
        int channels = switch (colour) {
            case 0, 3 -> 1;
            case 2 -> 3;
            case 4 -> 2;
            case 6 -> 4;
            default -> 0;
        };
        boolean depthAllowed = switch (colour) {
            case 0 -> depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
            case 3 -> depth == 1 || depth == 2 || depth == 4 || depth == 8;
            default -> depth == 8 || depth == 16;
        };
        if (channels == 0 || !depthAllowed || compression != 0 || filter != 0 || interlace > 1) {
            return "is damaged (its header: bit depth " + depth + ", colour type " + colour + ", compression " + compression
                   + ", filter " + filter + ", interlace " + interlace + ")";
        }
        int[][] passes = interlace == 1 ? ADAM7 : new int[][] {{0, 0, 1, 1}};
        rows = new long[passes.length];
        rowBytes = new long[passes.length];
        for (int p = 0; p < passes.length; p++) {
            long columns = Math.max(0, (w - passes[p][0] + passes[p][2] - 1) / passes[p][2]);
            rows[p] = columns == 0 ? 0 : Math.max(0, (ht - passes[p][1] + passes[p][3] - 1) / passes[p][3]);
            rowBytes[p] = 1 + (columns * channels * depth + 7) / 8;
            expected += rows[p] * rowBytes[p];
        }
        return null;
    }

    /** Decompresses {@code n} bytes of IDAT data, following the scanlines; why they are wrong, or null. */
    private String inflate(int n) {
        if (inflater.finished()) {
            return "is damaged (data follow the end of its compressed pixel data)";
        }
        inflater.setInput(buffer, 0, n);
        try {
            while (!inflater.needsInput() && !inflater.finished()) {
                int k = inflater.inflate(pixels);
                if (k == 0 && inflater.needsDictionary()) {
                    return "is damaged (its pixel data ask for a preset dictionary)";
                }
                String why = scanlines(k);
                if (why != null) {
                    return why;
                }
                if (k == 0 && !inflater.needsInput() && !inflater.finished()) {
                    return "is damaged (its pixel data do not decompress)";
                }
            }
        } catch (DataFormatException e) {
            return "is damaged (its pixel data do not decompress: " + e.getMessage() + ")";
        }
        if (inflater.finished() && inflater.getRemaining() > 0) {
            return "is damaged (data follow the end of its compressed pixel data)";
        }
        return null;
    }

    /** Follows {@code k} decompressed bytes through the scanlines: each row's first byte a filter type. */
    private String scanlines(int k) {
        decompressed += k;
        if (decompressed > expected) {
            return "is damaged (its pixel data hold more than the " + expected + " bytes its header makes)";
        }
        int i = 0;
        while (i < k) {
            while (row == rows[pass]) {
                pass++;
                row = 0;
            }
            if (inRow == 0 && (pixels[i] & 0xff) > 4) {
                return "is damaged (a row's filter type is " + (pixels[i] & 0xff) + "; 0 to 4 are defined)";
            }
            long take = Math.min(rowBytes[pass] - inRow, k - i);
            inRow += take;
            i += (int) take;
            if (inRow == rowBytes[pass]) {
                inRow = 0;
                row++;
            }
        }
        return null;
    }

    /** After IEND: the pixel data whole, and nothing more in the file. */
    private String end(boolean idat) throws IOException {
        if (!idat) {
            return "is damaged (it has no IDAT chunk)";
        }
        if (!inflater.finished()) {
            return "is damaged (its compressed pixel data end early)";
        }
        if (decompressed != expected) {
            return "is damaged (its pixel data hold " + decompressed + " bytes; its header makes " + expected + ")";
        }
        long extra = 0;
        for (int n; (n = in.read(buffer)) > 0; ) {
            extra += n;
        }
        return extra == 0 ? null : "is damaged (" + extra + " byte" + (extra == 1 ? " follows" : "s follow") + " its IEND chunk)";
    }
}

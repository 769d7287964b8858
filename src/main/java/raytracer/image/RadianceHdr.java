package raytracer.image;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads Radiance RGBE images (.hdr; Ward, "Real pixels", Graphics Gems II): a text header ended by
 * an empty line (any number of lines such as GAMMA= or PRIMARIES=, which are skipped), the
 * resolution line "-Y height +X width", then scanlines either flat or new-style run-length encoded.
 */
public final class RadianceHdr {
    private static final Pattern RESOLUTION = Pattern.compile("-Y (\\d+) \\+X (\\d+)");

    private RadianceHdr() {
    }

    public static Film read(Path file) throws IOException {
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            String magic = line(in);
            if (!magic.startsWith("#?")) {
                throw new IOException(file + ": not a Radiance HDR file (no #? signature)");
            }
            String text;
            while (!(text = line(in)).isEmpty()) {
                if (text.startsWith("FORMAT=") && !text.equals("FORMAT=32-bit_rle_rgbe")) {
                    throw new IOException(file + ": unsupported " + text + " (only 32-bit_rle_rgbe)");
                }
            }
            Matcher m = RESOLUTION.matcher(line(in));
            if (!m.matches()) {
                throw new IOException(file + ": unsupported orientation (only -Y h +X w)");
            }
            int height = size(m.group(1), file);
            int width = size(m.group(2), file);
            ImageFiles.requireHeap(file, width, height, 12);
            Film film = new Film(width, height);
            byte[] scan = new byte[4 * width];
            for (int y = 0; y < height; y++) {
                readScanline(in, scan, width, file);
                for (int x = 0; x < width; x++) {
                    int e = scan[4 * x + 3] & 0xff;
                    // value = (mantissa + 0.5) / 256 * 2^(e - 128), zero when e is 0
                    double f = e == 0 ? 0 : Math.scalb(1.0, e - 136);
                    film.set(x, y, ((scan[4 * x] & 0xff) + 0.5) * f, ((scan[4 * x + 1] & 0xff) + 0.5) * f,
                             ((scan[4 * x + 2] & 0xff) + 0.5) * f);
                }
            }
            return film;
        } catch (EOFException e) {
            throw new IOException(file + ": the image data ends early", e);
        }
    }

    private static void readScanline(InputStream in, byte[] scan, int width, Path file) throws IOException {
        int b0 = read(in);
        int b1 = read(in);
        int b2 = read(in);
        int b3 = read(in);
        boolean rle = b0 == 2 && b1 == 2 && (b2 & 0x80) == 0 && width >= 8 && width < 32768;
        if (!rle) {
            scan[0] = (byte) b0;
            scan[1] = (byte) b1;
            scan[2] = (byte) b2;
            scan[3] = (byte) b3;
            for (int i = 4; i < scan.length; i++) {
                scan[i] = (byte) read(in);
            }
            return;
        }
        if (((b2 << 8) | b3) != width) {
            throw new IOException(file + ": scanline width " + ((b2 << 8) | b3) + " does not match " + width);
        }
        // four planes (r, g, b, e), each a sequence of runs (count > 128) and literals
        for (int c = 0; c < 4; c++) {
            int x = 0;
            while (x < width) {
                int count = read(in);
                if (count > 128) {
                    count -= 128;
                    int value = read(in);
                    check(x + count <= width, file);
                    for (int i = 0; i < count; i++) {
                        scan[4 * x++ + c] = (byte) value;
                    }
                } else {
                    check(count > 0 && x + count <= width, file);
                    for (int i = 0; i < count; i++) {
                        scan[4 * x++ + c] = (byte) read(in);
                    }
                }
            }
        }
    }

    private static int size(String digits, Path file) throws IOException {
        try {
            return Integer.parseInt(digits);
        } catch (NumberFormatException e) {
            throw new IOException(file + ": image size " + digits + " is too large", e);
        }
    }

    private static void check(boolean ok, Path file) throws IOException {
        if (!ok) {
            throw new IOException(file + ": corrupt run-length data");
        }
    }

    private static int read(InputStream in) throws IOException {
        int b = in.read();
        if (b < 0) {
            throw new EOFException();
        }
        return b;
    }

    private static String line(InputStream in) throws IOException {
        StringBuilder s = new StringBuilder();
        int b;
        while ((b = read(in)) != '\n') {
            s.append((char) b);
        }
        return new String(s.toString().getBytes(StandardCharsets.ISO_8859_1), StandardCharsets.ISO_8859_1).strip();
    }
}

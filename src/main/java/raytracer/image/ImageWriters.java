package raytracer.image;

import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/** Writes a {@link Film} as PNG (sRGB, 8 bit) or PFM (linear 32-bit float), chosen by extension. */
public final class ImageWriters {
    public static final List<String> EXTENSIONS = List.of(".png", ".pfm");

    private ImageWriters() {
    }

    /** True when the file name ends in a supported extension. */
    public static boolean isSupported(Path path) {
        return isSupported(path.getFileName().toString());
    }

    /** Writes the film atomically: a failure never leaves a broken file in place of a good one. */
    public static void write(Film film, double exposure, Path path) throws IOException {
        write(film, exposure, true, path);
    }

    /**
     * As {@link #write(Film, double, Path)}; without {@code srgb} a PNG holds the clamped radiance as
     * its code values, as the report's images do (PFM output is linear either way).
     */
    public static void write(Film film, double exposure, boolean srgb, Path path) throws IOException {
        String name = path.getFileName().toString();
        if (!isSupported(name)) {
            throw new IOException("unsupported output format for " + path + " (use one of " + EXTENSIONS + ")");
        }
        AtomicFile.write(path, out -> encode(film, exposure, srgb, name, out));
    }

    /** True when a file name ends in a supported extension. */
    public static boolean isSupported(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        return EXTENSIONS.stream().anyMatch(lower::endsWith);
    }

    /**
     * The file's bytes onto {@code stream} (flushed, not closed), as {@link #write(Film, double, boolean, Path)}
     * writes them, in the format of the file name {@code name}'s extension: for an image stored
     * elsewhere (a file system of a cluster).
     */
    public static void encode(Film film, double exposure, boolean srgb, String name, OutputStream stream) throws IOException {
        String lower = name.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".png")) {
            DisplayCodes codes = new DisplayCodes(exposure, srgb);
            BufferedOutputStream out = new BufferedOutputStream(stream);
            PngEncoder.write(film.width(), film.height(), (y, rgb) -> {
                for (int x = 0, i = 0; x < film.width(); x++) {
                    for (int c = 0; c < 3; c++) {
                        rgb[i++] = (byte) codes.code(film.get(x, y, c));
                    }
                }
            }, out);
            out.flush();
        } else if (lower.endsWith(".pfm")) {
            writePfm(film, exposure, stream);
        } else {
            throw new IOException("unsupported output format for " + name + " (use one of " + EXTENSIONS + ")");
        }
    }

    /**
     * Stores a PFM of this program's own (a cached reference): written atomically, replacing whatever
     * is at {@code path} ({@link AtomicFile#replace}).
     */
    public static void storePfm(Film film, double exposure, Path path) throws IOException {
        AtomicFile.replace(path, out -> writePfm(film, exposure, out));
    }

    /** The bytes of the PFM {@link #writePfm} writes. */
    public static byte[] pfmBytes(Film film, double exposure) {
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        try {
            writePfm(film, exposure, bytes);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e); // a byte array does not fail
        }
        return bytes.toByteArray();
    }

    /**
     * Portable float map: header "PF", size, -1 for little endian; rows from the bottom. Every value
     * is finite (see {@link #finite}), so a reader never meets Inf or NaN.
     */
    static void writePfm(Film film, double exposure, OutputStream stream) throws IOException {
        DataOutputStream out = new DataOutputStream(new BufferedOutputStream(stream));
        out.write(("PF\n" + film.width() + " " + film.height() + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        ByteBuffer row = ByteBuffer.allocate(12 * film.width()).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = film.height() - 1; y >= 0; y--) {
            row.clear();
            for (int x = 0; x < film.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    row.putFloat(finite(film.get(x, y, c) * exposure));
                }
            }
            out.write(row.array(), 0, row.position());
        }
        out.flush();
    }

    /**
     * A radiance as a finite float. Past the float range (a film holds +Inf where a pixel's double
     * value overflowed it, for a light of intensity 1e308 say) it is the largest float of its sign:
     * still the brightest value, as the PNG's clamp to white shows it. NaN, which the renderer never
     * stores (it drops non-finite samples), becomes 0, as {@link ToneMap#toByte} makes it black.
     */
    static float finite(double radiance) {
        if (Double.isNaN(radiance)) {
            return 0;
        }
        return (float) Math.max(-Float.MAX_VALUE, Math.min(Float.MAX_VALUE, radiance));
    }

    /**
     * Reads a PFM written by {@link #writePfm} (or any little or big-endian colour PFM). A file that
     * is not one, or is cut short, is an IOException naming the file and what is wrong.
     */
    public static Film readPfm(Path path) throws IOException {
        return readPfm(java.nio.file.Files.readAllBytes(path), path);
    }

    /** As {@link #readPfm(Path)}, from the file's bytes already read; {@code path} names it in messages. */
    public static Film readPfm(byte[] bytes, Path path) throws IOException {
        int[] pos = {0};
        String magic = token(bytes, pos);
        if (magic.equals("Pf")) {
            throw new IOException(path + ": a greyscale PFM; a colour PFM (PF) is expected");
        }
        if (!magic.equals("PF")) {
            throw new IOException(path + ": not a PFM image (it does not start with 'PF')");
        }
        int width;
        int height;
        double scale;
        try {
            width = Integer.parseInt(token(bytes, pos));
            height = Integer.parseInt(token(bytes, pos));
            scale = Double.parseDouble(token(bytes, pos));
        } catch (NumberFormatException e) {
            throw new IOException(path + ": bad PFM header (width, height and scale expected after 'PF')");
        }
        if (width < 1 || height < 1 || (long) width * height > Film.MAX_PIXELS || scale == 0 || Double.isNaN(scale)) {
            throw new IOException(path + ": bad PFM header: " + width + "x" + height + " pixels, scale " + scale);
        }
        long expected = 12L * width * height;
        // the single whitespace byte after the header; a header written with CRLF line ends has
        // two, which the length tells apart from a first data byte that happens to be a LF
        boolean crlf = pos[0] + 1 < bytes.length && bytes[pos[0]] == '\r' && bytes[pos[0] + 1] == '\n'
                       && bytes.length - pos[0] - 2 == expected;
        pos[0] += crlf ? 2 : 1;
        if (bytes.length - pos[0] < expected) {
            throw new IOException(path + ": truncated PFM: " + Math.max(0, bytes.length - pos[0]) + " bytes of pixels, "
                                  + expected + " expected for " + width + "x" + height);
        }
        ByteBuffer data = ByteBuffer.wrap(bytes, pos[0], bytes.length - pos[0])
            .order(scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
        Film film = new Film(width, height);
        for (int y = height - 1; y >= 0; y--) {
            for (int x = 0; x < width; x++) {
                film.set(x, y, data.getFloat(), data.getFloat(), data.getFloat());
            }
        }
        return film;
    }

    /** The next whitespace-separated word of a header, empty at the end of the bytes. */
    private static String token(byte[] bytes, int[] pos) {
        while (pos[0] < bytes.length && Character.isWhitespace(bytes[pos[0]])) {
            pos[0]++;
        }
        int start = pos[0];
        while (pos[0] < bytes.length && !Character.isWhitespace(bytes[pos[0]]) && pos[0] - start < 32) {
            pos[0]++;
        }
        return new String(bytes, start, pos[0] - start, StandardCharsets.US_ASCII);
    }
}

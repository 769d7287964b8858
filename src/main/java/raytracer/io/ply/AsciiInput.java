package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Locale;

/**
 * ASCII PLY values: words separated by white space, as tinyply and trimesh read them (an element
 * need not end its line), each read whole and checked against its property's type as rply and
 * plyfile check it: an integer type takes an integer it holds (a uchar 0 to 255), a real type a
 * number, which must fit the type where it is used (1e39 is no float coordinate) but may
 * overflow where it is read past, as plyfile, trimesh and tinyply read it. Lines are counted (LF,
 * CR LF or CR alone end one) so that errors name them.
 */
final class AsciiInput extends PlyInput {
    /**
     * The longest word read: far past any number an exporter writes (a double prints in 25
     * characters or fewer; rply refuses words of 256), short enough that a file of one huge word
     * is refused rather than held.
     */
    static final int MAX_WORD = 1024;

    private final InputStream in;
    private final byte[] bytes = new byte[1 << 16];
    private int position;
    private int limit;
    private final StringBuilder word = new StringBuilder();
    /** The line the next character is on, and the line of the last word read. */
    private int line;
    private int wordLine;
    /** The last character was a CR: a LF right after it ends no further line. */
    private boolean afterCr;

    AsciiInput(InputStream in, int firstLine) {
        this.in = in;
        this.line = firstLine;
        this.wordLine = firstLine;
    }

    private int next() throws IOException {
        if (position == limit) {
            limit = in.read(bytes, 0, bytes.length);
            position = 0;
            if (limit <= 0) {
                limit = 0;
                return -1;
            }
        }
        return bytes[position++] & 0xff;
    }

    /** Whether {@code c} is white space (C's isspace), counting the line it ends. */
    private boolean blank(int c) {
        boolean cr = afterCr;
        afterCr = c == '\r';
        switch (c) {
            case '\n' -> {
                line += cr ? 0 : 1;
                return true;
            }
            case '\r' -> {
                line++;
                return true;
            }
            case ' ', '\t', '\f', 0x0b -> {
                return true;
            }
            default -> {
                return false;
            }
        }
    }

    private String word() throws IOException {
        int c;
        do {
            c = next();
        } while (c >= 0 && blank(c));
        if (c < 0) {
            throw new EOFException();
        }
        wordLine = line;
        word.setLength(0);
        while (c >= 0 && !blank(c)) {
            if (word.length() == MAX_WORD) {
                throw new BadValue("a word of more than " + MAX_WORD + " characters is not a number");
            }
            word.append((char) c);
            c = next();
        }
        return word.toString();
    }

    @Override
    double real(PlyType type) throws IOException {
        String w = word();
        if (type.isInteger()) {
            return integerOf(w, type);
        }
        double v = number(w);
        if (Double.isInfinite(v) && !notFinite(w)) {
            throw new BadValue("'" + PlyHeader.shown(w) + "' does not fit its type double (at most 1.79769e+308 in size)");
        }
        if (type == PlyType.FLOAT) {
            // the float the file declares, as a binary file holds it and plyfile and trimesh read it
            float f = (float) v;
            if (Float.isInfinite(f) && !Double.isInfinite(v)) {
                throw new BadValue("'" + PlyHeader.shown(w) + "' does not fit its type float (at most 3.40282e+38 in size)");
            }
            return f;
        }
        return v;
    }

    @Override
    long integer(PlyType type) throws IOException {
        if (!type.isInteger()) {
            throw new BadValue("a " + type + " where an integer is needed");
        }
        return integerOf(word(), type);
    }

    /** A value read past must still be one of its type; a real one may overflow, as numpy reads 1e39 as a float infinity. */
    @Override
    void skip(PlyType type) throws IOException {
        String w = word();
        if (type.isInteger()) {
            integerOf(w, type);
        } else {
            number(w);
        }
    }

    @Override
    int line() {
        return wordLine;
    }

    @Override
    boolean hasMore() throws IOException {
        int c;
        do {
            c = next();
        } while (c >= 0 && blank(c));
        wordLine = line;
        return c >= 0;
    }

    private static long integerOf(String w, PlyType type) throws BadValue {
        long v;
        try {
            v = Long.parseLong(w);
        } catch (NumberFormatException e) {
            if (!isInteger(w)) {
                throw new BadValue("'" + PlyHeader.shown(w) + "' is not an integer (its type is " + type + ")");
            }
            v = w.startsWith("-") ? Long.MIN_VALUE : Long.MAX_VALUE; // beyond a long, so beyond every type
        }
        if (!type.holds(v)) {
            throw new BadValue("'" + PlyHeader.shown(w) + "' does not fit its type " + type + " (" + type.range() + ")");
        }
        return v;
    }

    /** An optional sign and digits (of any number: Long.parseLong reads leading zeros without limit). */
    private static boolean isInteger(String w) {
        int start = w.startsWith("-") || w.startsWith("+") ? 1 : 0;
        if (start == w.length()) {
            return false;
        }
        for (int i = start; i < w.length(); i++) {
            if (w.charAt(i) < '0' || w.charAt(i) > '9') {
                return false;
            }
        }
        return true;
    }

    private static double number(String w) throws BadValue {
        try {
            return Double.parseDouble(w);
        } catch (NumberFormatException e) {
            return switch (w.toLowerCase(Locale.ROOT)) {
                // C's strtod (rply) and numpy (plyfile) spell the values that are not finite so
                case "inf", "+inf", "infinity", "+infinity" -> Double.POSITIVE_INFINITY;
                case "-inf", "-infinity" -> Double.NEGATIVE_INFINITY;
                case "nan", "+nan", "-nan" -> Double.NaN;
                default -> throw new BadValue("'" + PlyHeader.shown(w) + "' is not a number");
            };
        }
    }

    /** Whether {@code w} names a value that is not finite, rather than a number too large for a double. */
    private static boolean notFinite(String w) {
        String lower = w.toLowerCase(Locale.ROOT);
        return lower.contains("inf") || lower.contains("nan");
    }
}

package raytracer.cli;

import java.io.FilterWriter;
import java.io.IOException;
import java.io.Writer;

/**
 * What the command prints is safe on a terminal: a message echoes names from files and command
 * lines (a mesh path, a material, an output), and a name holding ESC, BEL, NUL or a right-to-left
 * override would otherwise recolour, ring, or reorder the user's terminal (escape injection).
 * Every character but newline and tab that is a control character or an invisible format
 * character is written as an escape ({@code \x1b}, {@code \u202e}); a message line is bounded.
 */
public final class Terminal {
    /** The longest message line printed; past it the line is cut and says how much was left out. */
    static final int MAX_LINE = 1000;

    private Terminal() {
    }

    /** A writer that escapes as the class comment says, around {@code out}. */
    public static Writer escaping(Writer out) {
        return new FilterWriter(out) {
            @Override
            public void write(int c) throws IOException {
                out.write(escape((char) c));
            }

            @Override
            public void write(char[] chars, int offset, int length) throws IOException {
                write(new String(chars, offset, length), 0, length);
            }

            @Override
            public void write(String text, int offset, int length) throws IOException {
                StringBuilder b = new StringBuilder(length);
                for (int i = offset; i < offset + length; i++) {
                    b.append(escape(text.charAt(i)));
                }
                out.write(b.toString());
            }
        };
    }

    /** The character as written to a terminal: itself, or an escape of it. */
    static String escape(char c) {
        if (c == '\n' || c == '\t') {
            return String.valueOf(c);
        }
        if (c < 0x20 || c == 0x7f) {
            return String.format("\\x%02x", (int) c);
        }
        // C1 controls, bidirectional and zero-width format characters, line and paragraph separators
        if (c >= 0x80 && c <= 0x9f || Character.getType(c) == Character.FORMAT || c == '\u2028' || c == '\u2029') {
            return String.format("\\u%04x", (int) c);
        }
        return String.valueOf(c);
    }

    /** A message on one line of at most {@link #MAX_LINE} characters. */
    public static String line(String message) {
        String line = message.replace('\n', ' ');
        if (line.length() <= MAX_LINE) {
            return line;
        }
        return line.substring(0, MAX_LINE - 40) + "... (" + String.format("%,d", line.length() - (MAX_LINE - 40))
               + " more characters)";
    }
}

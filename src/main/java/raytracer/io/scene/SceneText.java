package raytracer.io.scene;

import java.io.StringReader;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.reader.StreamReader;
import org.yaml.snakeyaml.scanner.Constant;

/**
 * The scene text as SnakeYAML's scanner reads it: code points with the line and column of the
 * current one. SnakeYAML's own {@link StreamReader} holds a window that it copies whole each time
 * it reads 1,024 more characters, and a token it scans is kept in the window until its end: one
 * long comment, word or run of spaces costs time quadratic in its length (a 4 MiB comment line
 * took 4.4 s, a 16 MiB one over a minute). The scene is in memory anyway, so this reader indexes
 * the whole text and every call is constant time (a prefix costs its length). It keeps
 * {@code StreamReader}'s counting: a line break is LF, NEL, LS, PS, or a CR not followed by LF;
 * a byte-order mark takes no column.
 */
final class SceneText extends StreamReader {
    private static final int BYTE_ORDER_MARK = 0xFEFF;
    private final String name;
    private final int[] text;
    private int pointer;
    private int line;
    private int column;
    private int documentIndex;

    /** The text, already checked by {@link #firstUnprintable} to hold only what YAML allows. */
    SceneText(String name, String text) {
        super(new StringReader(""));
        this.name = name;
        this.text = text.codePoints().toArray();
    }

    /** The index (in chars) of the first character YAML does not allow in a stream, or -1. */
    static int firstUnprintable(String text) {
        for (int i = 0; i < text.length(); ) {
            int c = text.codePointAt(i);
            if (!StreamReader.isPrintable(c)) {
                return i;
            }
            i += Character.charCount(c);
        }
        return -1;
    }

    @Override
    public Mark getMark() {
        // the whole text, not a copy: a mark costs nothing and its snippet is still right
        return new Mark(name, pointer, line, column, text, pointer);
    }

    @Override
    public void forward() {
        forward(1);
    }

    @Override
    public void forward(int length) {
        for (int i = 0; i < length && pointer < text.length; i++) {
            int c = text[pointer++];
            documentIndex++;
            if (Constant.LINEBR.has(c) || c == '\r' && pointer < text.length && text[pointer] != '\n') {
                line++;
                column = 0;
            } else if (c != BYTE_ORDER_MARK) {
                column++;
            }
        }
    }

    /** The current code point, or 0 at the end of the text (the scanner's end marker). */
    @Override
    public int peek() {
        return peek(0);
    }

    @Override
    public int peek(int index) {
        int at = pointer + index;
        return at < text.length ? text[at] : 0;
    }

    @Override
    public String prefix(int length) {
        return new String(text, pointer, Math.min(length, text.length - pointer));
    }

    /** As SnakeYAML's: the scanner calls it only on text without line breaks, so only the column moves. */
    @Override
    public String prefixForward(int length) {
        String prefix = prefix(length);
        pointer += length;
        documentIndex += length;
        column += length;
        return prefix;
    }

    @Override
    public int getColumn() {
        return column;
    }

    @Override
    public int getDocumentIndex() {
        return documentIndex;
    }

    @Override
    public void resetDocumentIndex() {
        documentIndex = 0;
    }

    @Override
    public int getIndex() {
        return pointer;
    }

    @Override
    public int getLine() {
        return line;
    }
}

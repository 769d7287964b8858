package raytracer.io.obj;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * Bytes of OBJ and MTL text to characters: UTF-8 when they are valid UTF-8, else ISO-8859-1, which
 * maps every byte to one character. Many exporters write Latin-1 names; read either way the ASCII
 * keywords and numbers are the same, and a name keeps one character per byte instead of becoming
 * U+FFFD, so an OBJ and its MTL decoded alike still agree on it.
 */
final class Decoding {
    /**
     * The characters, and the offset of the first byte that is not UTF-8 (-1 when all are). Text of
     * one byte a character (ASCII, or read as ISO-8859-1) is a {@link ByteChars} view of the bytes.
     */
    record Text(CharSequence chars, int latin1From) {
        /** The characters as a String (a copy, when they are a view of bytes). */
        String text() {
            return chars.toString();
        }

        /** The line (0-based) of the first byte that is not UTF-8: '\n', '\r' and "\r\n" each end one. */
        int latin1Line() {
            int lines = 0;
            for (int i = 0; i < latin1From; i++) {
                char c = chars.charAt(i);
                if (c == '\n' || c == '\r' && !(i + 1 < chars.length() && chars.charAt(i + 1) == '\n')) {
                    lines++;
                }
            }
            return lines;
        }
    }

    private static final byte[] BYTE_ORDER_MARK = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    private Decoding() {
    }

    /** The length of a UTF-8 byte-order mark at {@code bytes[0..length)}: 3, or 0 if there is none. */
    static int byteOrderMark(byte[] bytes, int length) {
        return length >= 3 && bytes[0] == BYTE_ORDER_MARK[0] && bytes[1] == BYTE_ORDER_MARK[1]
               && bytes[2] == BYTE_ORDER_MARK[2] ? 3 : 0;
    }

    /**
     * The text of {@code bytes[from .. to)}: a view of the bytes when they are ASCII (or not UTF-8,
     * read as ISO-8859-1), which must then stay as they are while the text is used; a String when
     * they hold UTF-8 sequences of several bytes.
     */
    static Text decode(byte[] bytes, int from, int to) {
        if (ascii(bytes, from, to)) {
            return new Text(new ByteChars(bytes, from, to), -1);
        }
        String text = new String(bytes, from, to - from, StandardCharsets.UTF_8);
        // the JDK's decoder writes U+FFFD for each malformed sequence; only then is the slower
        // strict decoder needed, to tell a U+FFFD written in the file from one
        if (text.indexOf('\uFFFD') < 0) {
            return new Text(text, -1);
        }
        int bad = firstMalformed(bytes, from, to);
        return bad < 0 ? new Text(text, -1) : new Text(new ByteChars(bytes, from, to), bad - from);
    }

    private static boolean ascii(byte[] bytes, int from, int to) {
        // the bytes' sign bits or-ed together: no branch per byte
        int any = 0;
        for (int i = from; i < to; i++) {
            any |= bytes[i];
        }
        return any >= 0;
    }

    /** The offset of the first byte that does not decode as UTF-8, or -1. */
    private static int firstMalformed(byte[] bytes, int from, int to) {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, from, to - from);
        CharBuffer out = CharBuffer.allocate(8192);
        while (true) {
            CoderResult result = decoder.decode(in, out, true);
            if (result.isError()) {
                return in.position();
            }
            if (result.isUnderflow()) {
                return -1;
            }
            out.clear(); // overflow: the characters themselves are not needed
        }
    }
}

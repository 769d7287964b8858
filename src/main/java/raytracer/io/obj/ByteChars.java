package raytracer.io.obj;

import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * Bytes read as characters one to one, as ISO-8859-1 decodes them (ASCII is the same): the text of a
 * chunk seen in the buffer it was read into, with no String made of it. The regular expressions
 * match on it as on a String; a line becomes a String only when a message quotes it or a name is
 * kept.
 */
final class ByteChars implements CharSequence {
    private final byte[] bytes;
    private final int from;
    private final int length;

    /** The characters of {@code bytes[from .. to)}, which must not change while this is in use. */
    ByteChars(byte[] bytes, int from, int to) {
        this.bytes = bytes;
        this.from = from;
        this.length = to - from;
    }

    /** The buffer seen, for its owner to reuse once this view is no longer used. */
    byte[] bytes() {
        return bytes;
    }

    @Override
    public int length() {
        return length;
    }

    @Override
    public char charAt(int index) {
        return (char) (bytes[from + Objects.checkIndex(index, length)] & 0xff);
    }

    /** The first index at or after {@code start} of the character {@code c} (below 256), or -1. */
    int indexOf(char c, int start) {
        byte b = (byte) c;
        for (int i = from + Math.max(0, start); i < from + length; i++) {
            if (bytes[i] == b) {
                return i - from;
            }
        }
        return -1;
    }

    @Override
    public CharSequence subSequence(int start, int end) {
        Objects.checkFromToIndex(start, end, length);
        return new String(bytes, from + start, end - start, StandardCharsets.ISO_8859_1);
    }

    @Override
    public String toString() {
        return new String(bytes, from, length, StandardCharsets.ISO_8859_1);
    }
}

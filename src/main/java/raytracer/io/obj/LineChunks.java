package raytracer.io.obj;

import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;

/**
 * Cuts a stream of OBJ text into chunks of whole lines, so that chunks can be parsed apart. A cut
 * falls only after a line end, '\n' or a '\r' that the next byte shows is not the first half of
 * "\r\n" (never inside a UTF-8 sequence), whose line does not end in a backslash, so a continued
 * line stays with the line it continues. A UTF-8 byte-order mark before the first line is dropped.
 */
final class LineChunks {
    /** About this many bytes a chunk: some 40,000 lines of a scanned mesh. */
    static final int CHUNK = 1 << 20;
    /** A chunk grows to hold one long line up to half this: a Java array (and string) ends below 2^31. */
    static final int MAX_BYTES = 1 << 30;

    private final InputStream in;
    private byte[] buffer = new byte[CHUNK + (1 << 16)];
    /** Bytes [0, filled) are read and not yet handed out. */
    private int filled;
    /** Bytes [CHUNK, scanned) hold no place to cut: one long line is searched once, not once a read. */
    private int scanned = CHUNK;
    private boolean ended;
    private boolean first = true;

    LineChunks(InputStream in) {
        this.in = in;
    }

    /** The next chunk, or null at the end of the stream. */
    Decoding.Text next() throws IOException {
        while (true) {
            int cut = filled >= CHUNK ? cutAfter(scanned) : -1;
            if (cut < 0 && ended) {
                cut = filled; // the rest
            }
            if (cut > 0) {
                int from = first ? Decoding.byteOrderMark(buffer, cut) : 0;
                first = false;
                Decoding.Text chunk = Decoding.decode(buffer, from, cut);
                System.arraycopy(buffer, cut, buffer, 0, filled - cut);
                filled -= cut;
                scanned = CHUNK;
                return chunk;
            }
            if (ended) {
                return null;
            }
            if (filled == buffer.length) {
                if (buffer.length > MAX_BYTES / 2) {
                    throw new IOException("a line longer than " + (buffer.length >> 20) + " MiB");
                }
                buffer = Arrays.copyOf(buffer, 2 * buffer.length); // one very long line
            }
            int read = in.read(buffer, filled, buffer.length - filled);
            if (read < 0) {
                ended = true;
            } else {
                filled += read;
            }
        }
    }

    /** The first place at or after {@code from} where a chunk may end, or -1 if none is read yet. */
    private int cutAfter(int from) {
        for (int i = from; i < filled; i++) {
            byte b = buffer[i];
            if (b == '\r' && i + 1 == filled) {
                scanned = i; // whether "\r\n" follows is known after the next read
                return -1;
            }
            if (b == '\n' || b == '\r' && buffer[i + 1] != '\n') {
                int last = b == '\n' && i > 0 && buffer[i - 1] == '\r' ? i - 2 : i - 1;
                if (last < 0 || buffer[last] != '\\') {
                    return i + 1;
                }
            }
        }
        scanned = Math.max(CHUNK, filled);
        return -1;
    }
}

package raytracer.io.obj;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Cuts a stream of OBJ text into chunks of whole lines, so that chunks can be parsed apart. A cut
 * falls only after a '\n' byte (never inside a UTF-8 sequence, never between '\r' and '\n') whose
 * line does not end in a backslash, so a continued line stays with the line it continues.
 */
final class LineChunks {
    /** About this many bytes a chunk: some 40,000 lines of a scanned mesh. */
    static final int CHUNK = 1 << 20;

    private final InputStream in;
    private byte[] buffer = new byte[CHUNK + (1 << 16)];
    /** Bytes [0, filled) are read and not yet handed out. */
    private int filled;
    private boolean ended;

    LineChunks(InputStream in) {
        this.in = in;
    }

    /** The next chunk, or null at the end of the stream. */
    String next() throws IOException {
        while (true) {
            int cut = filled >= CHUNK ? cutAfter(CHUNK) : -1;
            if (cut < 0 && ended) {
                cut = filled; // the rest
            }
            if (cut > 0) {
                String chunk = new String(buffer, 0, cut, StandardCharsets.UTF_8);
                System.arraycopy(buffer, cut, buffer, 0, filled - cut);
                filled -= cut;
                return chunk;
            }
            if (ended) {
                return null;
            }
            if (filled == buffer.length) {
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
            if (buffer[i] == '\n') {
                int last = i > 0 && buffer[i - 1] == '\r' ? i - 2 : i - 1;
                if (last < 0 || buffer[last] != '\\') {
                    return i + 1;
                }
            }
        }
        return -1;
    }
}

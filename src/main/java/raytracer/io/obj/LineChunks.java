package raytracer.io.obj;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayDeque;
import java.util.Arrays;

/**
 * Cuts a stream of OBJ text into chunks of whole lines, so that chunks can be parsed apart. A cut
 * falls only after a line end, '\n' or a '\r' that the next byte shows is not the first half of
 * "\r\n" (never inside a UTF-8 sequence), whose line does not end in a backslash, so a continued
 * line stays with the line it continues. A UTF-8 byte-order mark before the first line is dropped.
 *
 * <p>A chunk of one byte a character is handed out as a view of the buffer it was read into
 * ({@link Decoding}), and the reading goes on in another buffer; {@link #recycle} takes a chunk's
 * buffer back once the chunk is parsed, so a file of any size is read through the few buffers of
 * the chunks in flight rather than a new String of a megabyte per chunk.
 */
final class LineChunks {
    /** About this many bytes a chunk: some 40,000 lines of a scanned mesh. */
    static final int CHUNK = 1 << 20;
    /** A chunk grows to hold one long line up to half this: a Java array (and string) ends below 2^31. */
    static final int MAX_BYTES = 1 << 30;

    /** A buffer's usual size: a chunk and a read's worth past it, where the chunk's last line ends. */
    private static final int BUFFER = CHUNK + (1 << 16);

    private final InputStream in;
    private byte[] buffer = new byte[BUFFER];
    /** Buffers of chunks parsed, to read into again (used by one thread: the one that reads and merges). */
    private final ArrayDeque<byte[]> spare = new ArrayDeque<>();
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
                // the rest, read past the cut, starts the next buffer; a chunk decoded to a String
                // no longer needs its bytes
                byte[] next = chunk.chars() instanceof ByteChars ? spareBuffer(filled - cut) : buffer;
                System.arraycopy(buffer, cut, next, 0, filled - cut);
                buffer = next;
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

    /** A buffer to read on into, holding at least {@code rest} bytes. */
    private byte[] spareBuffer(int rest) {
        byte[] b = rest <= BUFFER ? spare.poll() : null;
        return b != null ? b : new byte[Math.max(BUFFER, rest)];
    }

    /** Takes back the buffer of a chunk that is no longer used (a view's; a String's needs none). */
    void recycle(Decoding.Text chunk) {
        if (chunk.chars() instanceof ByteChars view && view.bytes().length == BUFFER && view.bytes() != buffer) {
            spare.add(view.bytes());
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

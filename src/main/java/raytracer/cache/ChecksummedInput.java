package raytracer.cache;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.util.zip.CRC32C;
import raytracer.accel.BvhFile;

/**
 * Little-endian values read from the first {@code length} bytes of a file through a buffer of
 * {@value ChecksummedOutput#BUFFER} bytes, each byte counted into a CRC-32C as it arrives, for the
 * mesh cache: an entry's arrays are filled straight from the file instead of from a copy of the
 * whole file in memory. Reading past {@code length} is a {@link BufferUnderflowException}.
 */
final class ChecksummedInput implements BvhFile.Source {
    private final FileChannel channel;
    private final long length;
    private final ByteBuffer buffer = ByteBuffer.allocateDirect(ChecksummedOutput.BUFFER).order(ByteOrder.LITTLE_ENDIAN);
    private final CRC32C crc = new CRC32C();
    /** Bytes taken from the channel so far (the buffer's content included). */
    private long fetched;

    ChecksummedInput(FileChannel channel, long length) {
        this.channel = channel;
        this.length = length;
        buffer.limit(0);
    }

    /** Bytes read so far. */
    long position() {
        return fetched - buffer.remaining();
    }

    @Override
    public long remaining() {
        return length - position();
    }

    long getLong() {
        need(8);
        return buffer.getLong();
    }

    @Override
    public int getInt() {
        need(4);
        return buffer.getInt();
    }

    void getBytes(byte[] into) {
        for (int at = 0; at < into.length; ) {
            need(1);
            int n = Math.min(into.length - at, buffer.remaining());
            buffer.get(into, at, n);
            at += n;
        }
    }

    void getDoubles(double[] into) {
        for (int at = 0; at < into.length; ) {
            need(8);
            int n = Math.min(into.length - at, buffer.remaining() / 8);
            buffer.asDoubleBuffer().get(into, at, n);
            buffer.position(buffer.position() + 8 * n);
            at += n;
        }
    }

    @Override
    public void getFloats(float[] into) {
        for (int at = 0; at < into.length; ) {
            need(4);
            int n = Math.min(into.length - at, buffer.remaining() / 4);
            buffer.asFloatBuffer().get(into, at, n);
            buffer.position(buffer.position() + 4 * n);
            at += n;
        }
    }

    @Override
    public void getInts(int[] into) {
        for (int at = 0; at < into.length; ) {
            need(4);
            int n = Math.min(into.length - at, buffer.remaining() / 4);
            buffer.asIntBuffer().get(into, at, n);
            buffer.position(buffer.position() + 4 * n);
            at += n;
        }
    }

    /** Skips to the next multiple of 8 bytes. */
    void align() {
        skip((8 - position() % 8) % 8);
    }

    /** Reads past {@code bytes} bytes (still counted into the checksum). */
    void skip(long bytes) {
        for (long left = bytes; left > 0; ) {
            need(1);
            int n = (int) Math.min(left, buffer.remaining());
            buffer.position(buffer.position() + n);
            left -= n;
        }
    }

    /** The CRC-32C of the bytes before {@code length}, once every one of them is read ({@link #skip} the rest). */
    int checksum() {
        if (remaining() != 0) {
            throw new IllegalStateException(remaining() + " bytes are not read yet");
        }
        return (int) crc.getValue();
    }

    /** Makes at least {@code bytes} bytes available in the buffer, reading on as needed. */
    private void need(int bytes) {
        if (buffer.remaining() >= bytes) {
            return;
        }
        if (remaining() < bytes) {
            throw new BufferUnderflowException();
        }
        buffer.compact();
        try {
            while (buffer.position() < bytes) {
                int want = (int) Math.min(buffer.remaining(), length - fetched);
                int start = buffer.position();
                buffer.limit(start + want);
                if (channel.read(buffer) < 0) {
                    throw new IOException("it ends early (it shrank while it was read)");
                }
                ByteBuffer added = buffer.duplicate().position(start).limit(buffer.position());
                fetched += added.remaining();
                crc.update(added);
                buffer.limit(buffer.capacity());
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            buffer.flip();
        }
    }
}

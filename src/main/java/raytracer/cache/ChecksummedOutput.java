package raytracer.cache;

import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.zip.CRC32C;
import raytracer.accel.BvhFile;

/**
 * Little-endian values written through a buffer of {@value #BUFFER} bytes, with a CRC-32C of every
 * byte, for the mesh cache: an entry of a mesh of millions of triangles is streamed to its file
 * rather than assembled whole in memory first (it took the mesh's size again on the heap).
 */
final class ChecksummedOutput implements BvhFile.Sink {
    static final int BUFFER = 1 << 20;

    private final OutputStream out;
    private final ByteBuffer buffer = ByteBuffer.allocate(BUFFER).order(ByteOrder.LITTLE_ENDIAN);
    private final CRC32C crc = new CRC32C();
    private long written;

    ChecksummedOutput(OutputStream out) {
        this.out = out;
    }

    /** Bytes written so far. */
    long position() {
        return written + buffer.position();
    }

    void putLong(long value) {
        room(8);
        buffer.putLong(value);
    }

    @Override
    public void putInt(int value) {
        room(4);
        buffer.putInt(value);
    }

    void putBytes(byte[] values) {
        for (int at = 0; at < values.length; ) {
            room(1);
            int n = Math.min(values.length - at, buffer.remaining());
            buffer.put(values, at, n);
            at += n;
        }
    }

    void putDoubles(double[] values) {
        for (int at = 0; at < values.length; ) {
            room(8);
            int n = Math.min(values.length - at, buffer.remaining() / 8);
            buffer.asDoubleBuffer().put(values, at, n);
            buffer.position(buffer.position() + 8 * n);
            at += n;
        }
    }

    @Override
    public void putFloats(float[] values) {
        for (int at = 0; at < values.length; ) {
            room(4);
            int n = Math.min(values.length - at, buffer.remaining() / 4);
            buffer.asFloatBuffer().put(values, at, n);
            buffer.position(buffer.position() + 4 * n);
            at += n;
        }
    }

    @Override
    public void putInts(int[] values) {
        for (int at = 0; at < values.length; ) {
            room(4);
            int n = Math.min(values.length - at, buffer.remaining() / 4);
            buffer.asIntBuffer().put(values, at, n);
            buffer.position(buffer.position() + 4 * n);
            at += n;
        }
    }

    /** Zeros up to the next multiple of 8 bytes. */
    void pad() {
        while (position() % 8 != 0) {
            room(1);
            buffer.put((byte) 0);
        }
    }

    /** Writes the checksum of everything before it, and flushes. */
    void finish() throws IOException {
        int checksum = (int) crcAfterFlush();
        buffer.putInt(checksum);
        flush();
        out.flush();
    }

    private long crcAfterFlush() {
        flush();
        return crc.getValue();
    }

    /** Makes room for {@code bytes} more, writing out what the buffer holds when it lacks it. */
    private void room(int bytes) {
        if (buffer.remaining() < bytes) {
            flush();
        }
    }

    private void flush() {
        try {
            crc.update(buffer.array(), 0, buffer.position());
            out.write(buffer.array(), 0, buffer.position());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        written += buffer.position();
        buffer.clear();
    }
}

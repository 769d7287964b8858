package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Binary PLY values from a 64 KiB buffer, compacted and refilled when a value would cross its end.
 * Every value of a type fits it, so nothing is checked here: a scanned mesh's millions of values
 * cost a buffer read each and no allocation.
 */
final class BinaryInput extends PlyInput {
    private final InputStream in;
    private final byte[] bytes = new byte[1 << 16];
    private final ByteBuffer buffer;

    BinaryInput(InputStream in, ByteOrder order) {
        this.in = in;
        this.buffer = ByteBuffer.wrap(bytes).order(order);
        buffer.limit(0);
    }

    private void need(int n) throws IOException {
        if (buffer.remaining() >= n) {
            return;
        }
        buffer.compact();
        while (buffer.position() < n) {
            int read = in.read(bytes, buffer.position(), bytes.length - buffer.position());
            if (read < 0) {
                buffer.flip();
                throw new EOFException();
            }
            buffer.position(buffer.position() + read);
        }
        buffer.flip();
    }

    @Override
    double real(PlyType type) throws IOException {
        if (type.isInteger()) {
            return integer(type);
        }
        need(type.size);
        return type == PlyType.FLOAT ? buffer.getFloat() : buffer.getDouble();
    }

    @Override
    long integer(PlyType type) throws IOException {
        need(type.size);
        return switch (type) {
            case CHAR -> buffer.get();
            case UCHAR -> buffer.get() & 0xff;
            case SHORT -> buffer.getShort();
            case USHORT -> buffer.getShort() & 0xffff;
            case INT -> buffer.getInt();
            case UINT -> buffer.getInt() & 0xffffffffL;
            case FLOAT, DOUBLE -> throw new BadValue("a " + type + " where an integer is needed");
        };
    }

    @Override
    void skip(PlyType type) throws IOException {
        need(type.size);
        buffer.position(buffer.position() + type.size);
    }

    @Override
    int line() {
        return 0;
    }

    @Override
    boolean hasMore() throws IOException {
        try {
            need(1);
            return true;
        } catch (EOFException end) {
            return false;
        }
    }
}

package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * The values of a PLY body, one property value at a time in the header's types: binary of either
 * byte order through a buffer refilled from the stream, or ASCII as whitespace-separated numbers.
 * The end of the data is an {@link EOFException}; a word that is not a number of its type is a
 * {@link BadValue}; the loader adds the element and its number to either.
 */
abstract class PlyInput {
    /** A value that is not a number of its property's type (ASCII), with what was found. */
    static final class BadValue extends IOException {
        private static final long serialVersionUID = 1L;

        BadValue(String message) {
            super(message);
        }
    }

    abstract double real(PlyType type) throws IOException;

    /** An integer value (a list's count or a vertex index); a real number here is a BadValue. */
    abstract long integer(PlyType type) throws IOException;

    abstract void skip(PlyType type) throws IOException;

    static PlyInput of(PlyHeader.Format format, InputStream in) {
        return switch (format) {
            case ASCII -> new Ascii(in);
            case BINARY_LITTLE_ENDIAN -> new Binary(in, ByteOrder.LITTLE_ENDIAN);
            case BINARY_BIG_ENDIAN -> new Binary(in, ByteOrder.BIG_ENDIAN);
        };
    }

    /** Binary values from a 64 KiB buffer, compacted and refilled when a value would cross its end. */
    static final class Binary extends PlyInput {
        private final InputStream in;
        private final byte[] bytes = new byte[1 << 16];
        private final ByteBuffer buffer;

        Binary(InputStream in, ByteOrder order) {
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
    }

    /** ASCII values: words separated by white space (the line breaks between elements are not needed). */
    static final class Ascii extends PlyInput {
        private final InputStream in;
        private final byte[] bytes = new byte[1 << 16];
        private int position;
        private int limit;
        private final StringBuilder word = new StringBuilder();

        Ascii(InputStream in) {
            this.in = in;
        }

        private int next() throws IOException {
            if (position == limit) {
                limit = in.read(bytes, 0, bytes.length);
                position = 0;
                if (limit <= 0) {
                    limit = 0;
                    return -1;
                }
            }
            return bytes[position++] & 0xff;
        }

        private String word() throws IOException {
            int c;
            do {
                c = next();
            } while (c == ' ' || c == '\t' || c == '\n' || c == '\r');
            if (c < 0) {
                throw new EOFException();
            }
            word.setLength(0);
            while (c >= 0 && c != ' ' && c != '\t' && c != '\n' && c != '\r') {
                if (word.length() < 64) {
                    word.append((char) c);
                }
                c = next();
            }
            return word.toString();
        }

        @Override
        double real(PlyType type) throws IOException {
            String w = word();
            if (type.isInteger()) {
                return integerOf(w, type);
            }
            try {
                return Double.parseDouble(w);
            } catch (NumberFormatException e) {
                throw new BadValue("'" + PlyHeader.shown(w) + "' is not a number");
            }
        }

        @Override
        long integer(PlyType type) throws IOException {
            return integerOf(word(), type);
        }

        private static long integerOf(String w, PlyType type) throws BadValue {
            try {
                return Long.parseLong(w);
            } catch (NumberFormatException e) {
                throw new BadValue("'" + PlyHeader.shown(w) + "' is not an integer (its type is " + type + ")");
            }
        }

        @Override
        void skip(PlyType type) throws IOException {
            word();
        }
    }
}

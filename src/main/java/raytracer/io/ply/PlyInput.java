package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteOrder;

/**
 * The values of a PLY body, one property value at a time in the header's types: binary of either
 * byte order ({@link BinaryInput}) or ASCII words ({@link AsciiInput}). The end of the data is an
 * {@link EOFException}; a value that is not one of its type is a {@link BadValue}; the loader
 * adds the file, line, element and row to either.
 */
abstract class PlyInput {
    /** A value that is not one of its property's type, with what was found. */
    static final class BadValue extends IOException {
        private static final long serialVersionUID = 1L;

        BadValue(String message) {
            super(message);
        }
    }

    abstract double real(PlyType type) throws IOException;

    /** An integer value (a list's count or a vertex index) of an integer {@code type}. */
    abstract long integer(PlyType type) throws IOException;

    abstract void skip(PlyType type) throws IOException;

    /** The line of the value read last (ASCII), or 0 where a body has no lines (binary). */
    abstract int line();

    /** Whether the body goes on (ASCII: with more than white space); at its end, after the header's last element. */
    abstract boolean hasMore() throws IOException;

    /** The body of {@code format} from {@code in}, whose first line (ASCII) is {@code firstLine} of the file. */
    static PlyInput of(PlyHeader.Format format, InputStream in, int firstLine) {
        return switch (format) {
            case ASCII -> new AsciiInput(in, firstLine);
            case BINARY_LITTLE_ENDIAN -> new BinaryInput(in, ByteOrder.LITTLE_ENDIAN);
            case BINARY_BIG_ENDIAN -> new BinaryInput(in, ByteOrder.BIG_ENDIAN);
        };
    }
}

package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.util.List;

/**
 * The body of a PLY file as its element readers see it: the values ({@link #in}) and where an
 * error is, the file, the line (ASCII) and the element's row. An error in the first row of an
 * element that follows another says where that one ended: a header that declares fewer vertices
 * than the body has shows first where the faces are read from vertex data.
 */
final class PlyBody {
    final PlyInput in;
    private final String file;
    private final List<PlyHeader.Element> elements;
    private final String skipped;

    PlyBody(String file, PlyHeader header, PlyInput in) {
        this.file = file;
        this.elements = header.elements();
        this.skipped = header.skipped();
        this.in = in;
    }

    /** An error of the whole file. */
    PlyException error(String message) {
        return new PlyException(file + ": " + message);
    }

    /**
     * An element or property the file lacks: when the header had a line of an unknown keyword,
     * say so, as it may be the one meant ("elemnt vertex 3").
     */
    PlyException missing(String message) {
        return error(message + (skipped == null ? "" : " (skipped: " + skipped + ")"));
    }

    /** "file[:line]: element i (of n, counting from 0): " */
    String at(PlyHeader.Element e, long i) {
        int line = in.line();
        return file + (line > 0 ? ":" + line : "") + ": " + PlyHeader.shown(e.name()) + " " + i + " (of " + e.count()
               + ", counting from 0): ";
    }

    /** An error in row {@code i} of {@code e}. */
    PlyException error(PlyHeader.Element e, long i, String message) {
        return new PlyException(at(e, i) + message + afterPrevious(e, i));
    }

    /** A value of {@code property} that is not one of its type. */
    PlyException bad(PlyHeader.Element e, long i, PlyHeader.Property property, PlyInput.BadValue bad) {
        return error(e, i, "property '" + PlyHeader.shown(property.name()) + "': " + bad.getMessage());
    }

    PlyException truncated(PlyHeader.Element e, long i) {
        return new PlyException(at(e, i) + "the file ends early (truncated)");
    }

    private String afterPrevious(PlyHeader.Element e, long i) {
        int k = 0;
        while (k < elements.size() && elements.get(k) != e) {
            k++;
        }
        if (i != 0 || k == 0 || k == elements.size() || elements.get(k - 1).count() == 0) {
            return "";
        }
        PlyHeader.Element previous = elements.get(k - 1);
        return "; the header's " + previous.count() + " '" + PlyHeader.shown(previous.name())
               + "' elements end here: if the body has more, the header declares too few";
    }

    /** Reads past a value of {@code property}, a scalar or a list. */
    void skip(PlyHeader.Property property) throws IOException {
        if (!property.isList()) {
            in.skip(property.type());
            return;
        }
        long n = in.integer(property.countType());
        if (n < 0) {
            throw new PlyInput.BadValue("a list of " + n + " values");
        }
        for (long j = 0; j < n; j++) {
            in.skip(property.type());
        }
    }

    /** Reads past every row of {@code e}. */
    void skipAll(PlyHeader.Element e) throws IOException, PlyException {
        for (long i = 0; i < e.count(); i++) {
            PlyHeader.Property property = null;
            try {
                for (PlyHeader.Property p : e.properties()) {
                    property = p;
                    skip(p);
                }
            } catch (EOFException end) {
                throw truncated(e, i);
            } catch (PlyInput.BadValue bad) {
                throw bad(e, i, property, bad);
            }
        }
    }
}

package raytracer.io.obj;

import java.util.Arrays;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import raytracer.shapes.mesh.Growing;

/**
 * The faces of an OBJ file as corner triples (v, vt, vn) of triangles: each face's indices
 * resolved against what was defined before its line, then fan-triangulated, (0, i, i + 1), whatever
 * its number of corners. A vertex that does not exist stops the load; a texture coordinate or
 * normal that does not exist is dropped from its face, with one warning a file, and a face of
 * fewer than three corners is skipped, with one warning a file too.
 */
final class Faces {
    /**
     * One corner of a face, right after the one before it (\G): v, v/vt, v//vn or v/vt/vn, where an
     * empty slot ("1//", "1/2/") names nothing. It is found corner by corner: a repeated group
     * matching the whole face recurses once a corner in java.util.regex and overflowed the stack
     * at some 3,000 corners.
     */
    private static final Pattern CORNER = Pattern.compile("\\G\\s+([-+]?\\d+)(?:/([-+]?\\d*)(?:/([-+]?\\d*))?)?(?![^\\s#])");
    private static final Pattern FACE_END = Pattern.compile("\\s*(?:#.*)?");
    private static final String FORMS = "'f' and at least 3 corners 'v', 'v/vt', 'v//vn' or 'v/vt/vn'";

    private final String name;
    private final FileWarnings warnings;
    private final Matcher corner = CORNER.matcher("");
    private final Matcher faceEnd = FACE_END.matcher("");
    /** Corner triples of all triangles: v always, vt and vn once any corner has them (else null). */
    final Growing.Ints cornerV = new Growing.Ints();
    Growing.Ints cornerVt;
    Growing.Ints cornerVn;
    /** The face being read: its corners' indices, and the first attribute index that does not exist, as written. */
    private final Buffers.Ints faceV = new Buffers.Ints();
    private final Buffers.Ints faceVt = new Buffers.Ints();
    private final Buffers.Ints faceVn = new Buffers.Ints();
    private String missingVt;
    private String missingVn;
    /** The text holding the line being read, and the line in it, [lineStart, lineEnd). */
    private CharSequence text;
    private int lineStart;
    private int lineEnd;
    private int lineNumber;
    int faces;
    /** Faces of more than three corners. */
    int ngons;

    Faces(String name, FileWarnings warnings) {
        this.name = name;
        this.warnings = warnings;
    }

    /** Triangles so far. */
    int triangles() {
        return cornerV.size() / 3;
    }

    /** Appends {@code count} corners of triangles with positions only, 0-based and in range. */
    void addPlain(int[] corners, int count) {
        cornerV.addAll(corners, count);
        if (cornerVt != null) {
            cornerVt.fill(-1, count);
        }
        if (cornerVn != null) {
            cornerVn.fill(-1, count);
        }
        faces += count / 3;
    }

    /** Sets the line the next face is read from: [start, end) of {@code text}, line {@code lineNumber} of the file. */
    void at(CharSequence text, int start, int end, int lineNumber) {
        this.text = text;
        this.lineStart = start;
        this.lineEnd = end;
        this.lineNumber = lineNumber;
    }

    /** The face of the line ({@link #at}) whose corners follow {@code from}; returns how many triangles it made. */
    int read(int from, int vertices, int uvs, int normals) throws ObjException {
        faceV.size = 0;
        faceVt.size = 0;
        faceVn.size = 0;
        missingVt = null;
        missingVn = null;
        String badVertex = null;
        int end = from;
        corner.reset(text).region(from, lineEnd);
        while (corner.find()) {
            int v = index(corner.start(1), corner.end(1), vertices);
            if (v < 0 && badVertex == null) {
                badVertex = outOfRange(corner.group(1), vertices);
            }
            faceV.add(v);
            faceVt.add(attribute(2, uvs, true));
            faceVn.add(attribute(3, normals, false));
            end = corner.end();
        }
        // a syntax error anywhere on the line is reported before a vertex index out of range
        if (!faceEnd.reset(text).region(end, lineEnd).matches()) {
            throw error("expected " + FORMS + ", got '" + FileWarnings.shown(text.subSequence(lineStart, lineEnd).toString(), 60) + "'");
        }
        if (badVertex != null) {
            throw error(badVertex);
        }
        int count = faceV.size;
        if (count < 3) {
            // no triangle: tinyobjloader skips such a face with a warning ("Degenerated face found")
            warnings.tally("degenerate", lineNumber, n -> "a face of " + count + (count == 1 ? " corner" : " corners")
                + " has no triangle; " + n + (n == 1 ? " face" : " faces") + " of fewer than 3 corners skipped");
            return 0;
        }
        if (present(faceVt, missingVt, "texture coordinate", uvs) && cornerVt == null) {
            cornerVt = new Growing.Ints();
            cornerVt.fill(-1, cornerV.size());
        }
        if (present(faceVn, missingVn, "normal", normals) && cornerVn == null) {
            cornerVn = new Growing.Ints();
            cornerVn.fill(-1, cornerV.size());
        }
        for (int i = 1; i + 1 < count; i++) {
            addCorner(0);
            addCorner(i);
            addCorner(i + 1);
        }
        faces++;
        ngons += count > 3 ? 1 : 0;
        return count - 2;
    }

    /**
     * The 0-based texture coordinate or normal of the corner's {@code group}: -1 when the slot is
     * absent or empty, -2 when it names one that does not exist (the first such is kept as written).
     */
    private int attribute(int group, int count, boolean uv) {
        int start = corner.start(group);
        int end = corner.end(group);
        if (start >= end) {
            return -1;
        }
        int index = index(start, end, count);
        if (index < 0 && (uv ? missingVt : missingVn) == null) {
            if (uv) {
                missingVt = corner.group(group);
            } else {
                missingVn = corner.group(group);
            }
        }
        return index < 0 ? -2 : index;
    }

    /**
     * True if some corner of the face has the attribute. If a corner names one that does not
     * exist ({@code missing} as written), the whole face goes without: one warning a file, with
     * the count of faces.
     */
    private boolean present(Buffers.Ints indices, String missing, String what, int count) {
        if (missing != null) {
            String defined = count == 0 ? "none" : Integer.toString(count);
            warnings.tally(what, lineNumber, n -> what + " index " + missing + " does not exist (" + defined
                + " defined so far); " + n + (n == 1 ? " face" : " faces") + " naming " + what + "s that do not exist "
                + (n == 1 ? "is" : "are") + " kept without them");
            Arrays.fill(indices.data, 0, indices.size, -1);
            return false;
        }
        for (int i = 0; i < indices.size; i++) {
            if (indices.data[i] >= 0) {
                return true;
            }
        }
        return false;
    }

    private void addCorner(int i) {
        cornerV.add(faceV.data[i]);
        if (cornerVt != null) {
            cornerVt.add(faceVt.data[i]);
        }
        if (cornerVn != null) {
            cornerVn.add(faceVn.data[i]);
        }
    }

    /** "f a b c" with positive indices, spans of the line ({@link #at}): no corner loop, no fan. */
    void addTriangle(int vertices, Matcher plain) throws ObjException {
        for (int g = 1; g <= 3; g++) {
            int v = index(plain.start(g), plain.end(g), vertices);
            if (v < 0) {
                throw error(outOfRange(plain.group(g), vertices));
            }
            cornerV.add(v);
            if (cornerVt != null) {
                cornerVt.add(-1);
            }
            if (cornerVn != null) {
                cornerVn.add(-1);
            }
        }
        faces++;
    }

    /** A 0-based index from a 1-based or negative (relative) OBJ index, or -1 if not in [0, count). */
    private int index(int start, int end, int count) {
        int index = Numbers.parseInt(text, start, end);
        int resolved = index > 0 ? index - 1 : count + index;
        return index == 0 || resolved < 0 || resolved >= count ? -1 : resolved;
    }

    /** The index as written: one past the int range would print as the saturated 2147483647. */
    private static String outOfRange(String written, int count) {
        return "vertex index " + written + " is out of range (" + (count == 0 ? "no vertex is defined before this line)"
            : count + " defined so far; indices are 1.." + count + " or -1..-" + count + ")");
    }

    private ObjException error(String message) {
        return new ObjException(name + ":" + lineNumber + ": " + message);
    }
}

package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.Set;

/**
 * The {@code face} element's vertex_indices (or vertex_index) lists, fan-triangulated (0, c, c + 1):
 * the triangles trimesh makes of them. The indices are of any integer type, or of a real one
 * holding whole numbers (plyfile and trimesh read both). A face of fewer than three corners has no
 * triangle: trimesh leaves it out, tinyobjloader skips such a face of an OBJ file with a warning,
 * and so it is skipped here, with one warning for all. Arrays grow as faces arrive, whatever the
 * header says.
 */
final class PlyFaces {
    /** More corners than this in one face is not a scanned mesh's polygon. */
    static final int MAX_CORNERS = 1 << 16;
    /** The most triangle corners a Java int array holds, with room for the VM's header. */
    private static final int MAX_CORNER_INDICES = Integer.MAX_VALUE - 8;
    /** At most this many faces' triangles are set aside from a header's count before they arrive. */
    private static final int FIRST_CAPACITY = 1 << 20;

    int[] triangles = new int[0];
    int corners;
    /** Faces that gave triangles, and those of them of more than three corners. */
    int faces;
    int ngons;
    /** Faces of fewer than three corners, skipped; the first of them, as its warning places it. */
    long degenerate;
    String firstDegenerate;

    /** Reads the rows of {@code e}, whose indices are below {@code vertices}, naming the properties read past in {@code skipped}. */
    static PlyFaces read(PlyHeader.Element e, PlyBody body, long vertices, Set<String> skipped) throws IOException, PlyException {
        List<PlyHeader.Property> properties = e.properties();
        int list = -1;
        for (int k = 0; k < properties.size() && list < 0; k++) {
            String name = properties.get(k).name();
            if (properties.get(k).isList() && (name.equals("vertex_indices") || name.equals("vertex_index"))) {
                list = k;
            }
        }
        if (list < 0) {
            throw body.missing("the face element needs a list property vertex_indices (or vertex_index)");
        }
        for (int k = 0; k < properties.size(); k++) {
            if (k != list) {
                skipped.add("face property '" + PlyHeader.shown(properties.get(k).name()) + "'");
            }
        }
        PlyFaces read = new PlyFaces();
        read.triangles = new int[3 * (int) Math.min(e.count(), FIRST_CAPACITY)];
        read.fill(e, body, list, vertices);
        return read;
    }

    private void fill(PlyHeader.Element e, PlyBody body, int list, long vertices) throws IOException, PlyException {
        PlyInput in = body.in;
        List<PlyHeader.Property> properties = e.properties();
        PlyHeader.Property indices = properties.get(list);
        boolean realIndices = !indices.type().isInteger();
        int[] face = new int[16];
        int rows = (int) e.count();
        for (int i = 0; i < rows; i++) {
            int size = 0;
            for (int k = 0; k < properties.size(); k++) {
                PlyHeader.Property property = properties.get(k);
                try {
                    if (k != list) {
                        body.skip(property);
                        continue;
                    }
                    long count = in.integer(indices.countType());
                    if (count < 0 || count > MAX_CORNERS) {
                        throw body.error(e, i, count < 0 ? "a list of " + count + " vertices"
                                                         : "a face of " + count + " corners; at most " + MAX_CORNERS + " are read");
                    }
                    size = (int) count;
                    if (face.length < size) {
                        face = new int[Math.max(size, 2 * face.length)];
                    }
                    for (int c = 0; c < size; c++) {
                        long index = realIndices ? whole(in.real(indices.type())) : in.integer(indices.type());
                        if (index < 0 || index >= vertices) {
                            throw body.error(e, i, "vertex index " + index + " is out of range (the file has " + vertices + " vertices)");
                        }
                        face[c] = (int) index;
                    }
                } catch (EOFException end) {
                    throw body.truncated(e, i);
                } catch (PlyInput.BadValue bad) {
                    throw body.bad(e, i, property, bad);
                }
            }
            if (size < 3) {
                if (degenerate++ == 0) {
                    firstDegenerate = body.at(e, i) + "a face of " + size + (size == 1 ? " corner" : " corners") + " has no triangle";
                }
            } else {
                addFan(face, size, e, i, body);
            }
        }
    }

    /** A vertex index of a real type, as plyfile and trimesh read it: a whole number. */
    private static long whole(double index) throws PlyInput.BadValue {
        if (index != Math.rint(index)) {
            throw new PlyInput.BadValue("vertex index " + index + " is not a whole number");
        }
        return (long) index;
    }

    /** Adds the face's fan of triangles (0, c, c + 1), growing the array as faces arrive. */
    private void addFan(int[] face, int size, PlyHeader.Element e, int i, PlyBody body) throws PlyException {
        int added = 3 * (size - 2);
        if (corners > MAX_CORNER_INDICES - added) {
            throw body.error(e, i, "more than " + MAX_CORNER_INDICES / 3 + " triangles do not fit one mesh");
        }
        if (corners + added > triangles.length) {
            long grown = Math.max((long) corners + added, 2L * triangles.length);
            triangles = Arrays.copyOf(triangles, (int) Math.min(grown, MAX_CORNER_INDICES));
        }
        for (int c = 1; c + 1 < size; c++) {
            triangles[corners++] = face[0];
            triangles[corners++] = face[c];
            triangles[corners++] = face[c + 1];
        }
        faces++;
        if (size > 3) {
            ngons++;
        }
    }
}

package raytracer.io.ply;

import java.io.EOFException;
import java.io.IOException;
import java.util.Arrays;
import java.util.Set;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Growing;

/**
 * The {@code vertex} element: x, y, z, and the normals nx, ny, nz and texture coordinates (u, v;
 * s, t; texture_u, texture_v) when all of a set are there, in any order among other properties,
 * which are read past. A position holds what a triangle does ({@link Triangle#MAX_COORDINATE});
 * normals and texture coordinates are kept as floats, so each must fit one (a double normal of
 * 1e300 became an infinite float, and the mesh rendered black). The header's count may be
 * overstated by a damaged or hostile file, so arrays grow as values arrive rather than being
 * sized from it.
 */
final class PlyVertices {
    /** At most this many values are set aside from a header's count before they arrive. */
    private static final int FIRST_CAPACITY = 1 << 20;

    final int count;
    final Growing.Doubles positions = new Growing.Doubles();
    float[] normals;
    float[] uvs;

    private PlyVertices(int count) {
        this.count = count;
    }

    /** Reads the rows of {@code e}, naming the properties read past in {@code skipped}. */
    static PlyVertices read(PlyHeader.Element e, PlyBody body, Set<String> skipped) throws IOException, PlyException {
        if (e.count() > Integer.MAX_VALUE / 3) {
            throw body.error(e.count() + " vertices; at most " + Integer.MAX_VALUE / 3 + " fit one mesh");
        }
        int x = e.scalar("x");
        int y = e.scalar("y");
        int z = e.scalar("z");
        if (x < 0 || y < 0 || z < 0) {
            throw body.missing("the vertex element needs scalar properties x, y and z");
        }
        int nx = e.scalar("nx");
        int ny = e.scalar("ny");
        int nz = e.scalar("nz");
        boolean hasNormals = nx >= 0 && ny >= 0 && nz >= 0;
        int u = e.scalar("u", "s", "texture_u", "texture_s");
        int v = e.scalar("v", "t", "texture_v", "texture_t");
        boolean hasUvs = u >= 0 && v >= 0;
        // the property of each slot (0-2 position, 3-5 normal, 6-7 texture coordinate), and the slot of each property (-1: read past)
        int[] property = {x, y, z, nx, ny, nz, u, v};
        int[] slot = new int[e.properties().size()];
        Arrays.fill(slot, -1);
        for (int k = 0; k < 8; k++) {
            if (k < 3 || (k < 6 ? hasNormals : hasUvs)) {
                slot[property[k]] = k;
            }
        }
        for (int i = 0; i < slot.length; i++) {
            if (slot[i] < 0) {
                skipped.add("vertex property '" + PlyHeader.shown(e.properties().get(i).name()) + "'");
            }
        }
        PlyVertices read = new PlyVertices((int) e.count());
        read.fill(e, body, slot, property, hasNormals, hasUvs);
        return read;
    }

    private void fill(PlyHeader.Element e, PlyBody body, int[] slot, int[] property, boolean hasNormals, boolean hasUvs)
        throws IOException, PlyException {
        PlyInput in = body.in;
        int capacity = Math.min(count, FIRST_CAPACITY);
        float[] n = hasNormals ? new float[3 * capacity] : null;
        float[] t = hasUvs ? new float[2 * capacity] : null;
        double[] values = new double[8];
        for (int i = 0; i < count; i++) {
            if (i == capacity) {
                capacity = (int) Math.min(count, 2L * capacity);
                n = n != null ? Arrays.copyOf(n, 3 * capacity) : null;
                t = t != null ? Arrays.copyOf(t, 2 * capacity) : null;
            }
            for (int k = 0; k < slot.length; k++) {
                PlyHeader.Property p = e.properties().get(k);
                try {
                    if (slot[k] < 0) {
                        body.skip(p);
                    } else {
                        values[slot[k]] = in.real(p.type());
                    }
                } catch (EOFException end) {
                    throw body.truncated(e, i);
                } catch (PlyInput.BadValue bad) {
                    throw body.bad(e, i, p, bad);
                }
            }
            for (int k = 0; k < 8; k++) {
                if (!(Math.abs(values[k]) <= (k < 3 ? Triangle.MAX_COORDINATE : Float.MAX_VALUE))) {
                    throw outOfRange(values[k], k, e, i, body, property);
                }
            }
            positions.add(values[0]);
            positions.add(values[1]);
            positions.add(values[2]);
            if (n != null) {
                n[3 * i] = (float) values[3];
                n[3 * i + 1] = (float) values[4];
                n[3 * i + 2] = (float) values[5];
            }
            if (t != null) {
                t[2 * i] = (float) values[6];
                t[2 * i + 1] = (float) values[7];
            }
        }
        normals = n;
        uvs = t;
    }

    /** The error of a value not finite or beyond what its slot keeps (NaN fails every comparison). */
    private static PlyException outOfRange(double value, int k, PlyHeader.Element e, int i, PlyBody body, int[] property) {
        String name = "property '" + PlyHeader.shown(e.properties().get(property[k]).name()) + "': ";
        if (!Double.isFinite(value)) {
            return body.error(e, i, name + "its " + (k < 3 ? "position" : k < 6 ? "normal" : "texture coordinate")
                                    + " is not finite (" + value + ")");
        }
        return body.error(e, i, name + (k < 3 ? "its position coordinate " + value + " is beyond " + Triangle.MAX_COORDINATE
                                                 + " in size, more than a triangle holds"
                                              : (k < 6 ? "normal component " : "texture coordinate ") + value
                                                + " is beyond the largest float (3.40282e+38)"));
    }
}

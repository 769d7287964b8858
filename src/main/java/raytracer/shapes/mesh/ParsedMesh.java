package raytracer.shapes.mesh;

import java.util.Arrays;
import raytracer.math.BBox;

/**
 * A mesh as a loader read it, in the file's order: its positions still in the {@link Growing}
 * blocks they arrived in, everything else in flat arrays as {@link Mesh} holds them. The renderer
 * never traces it: its BVH is built over it and {@link #afterTrianglesMoved} makes the {@link Mesh}
 * in the tree's leaf order, the one flat copy of the positions there is (flattened here first and
 * copied again in leaf order, they took their memory three times over). {@link #mesh} is a flat
 * copy in file order, for whoever wants one (tests, a mesh's own figures).
 */
public final class ParsedMesh {
    private final Growing.Doubles positions;
    private final float[] normals;
    private final float[] uvs;
    private final int[] triangles;
    private final int[] materialIds;
    private final int vertices;

    /** Takes over {@code positions} (x, y, z per vertex); the rest as {@link Mesh#Mesh} takes it. */
    public ParsedMesh(Growing.Doubles positions, float[] normals, float[] uvs, int[] triangles, int[] materialIds) {
        vertices = Mesh.checkArrays(positions.size(), normals, uvs, triangles, materialIds);
        this.positions = positions;
        this.normals = normals;
        this.uvs = uvs;
        this.triangles = triangles;
        this.materialIds = materialIds;
    }

    public int vertexCount() {
        return vertices;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    /** Coordinate {@code i} of the positions, x, y, z per vertex. */
    public double position(int i) {
        return positions.get(i);
    }

    /** Offset into the positions of corner {@code k} (0, 1, 2) of triangle {@code tri}. */
    public int corner(int tri, int k) {
        return 3 * triangles[3 * tri + k];
    }

    /** The vertex indices of all triangles, three each (not a copy). */
    public int[] triangles() {
        return triangles;
    }

    public boolean hasNormals() {
        return normals != null;
    }

    public boolean hasUvs() {
        return uvs != null;
    }

    public int[] materialIds() {
        return materialIds;
    }

    public BBox bounds() {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int i = 0; i < 3 * vertices; i++) {
            double p = positions.get(i);
            lo[i % 3] = Math.min(lo[i % 3], p);
            hi[i % 3] = Math.max(hi[i % 3], p);
        }
        return new BBox(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    }

    /** The mesh in file order, its positions copied flat and its other arrays shared. */
    public Mesh mesh() {
        return new Mesh(positions.copy(), normals, uvs, triangles, materialIds);
    }

    /**
     * The mesh in a BVH's leaf order, once its triangles have been moved there, in place, by the
     * builder, which carries {@link #triangles()} along with the triangles' boxes
     * ({@code MedianSplitBuilder.build(boxes, triangles)}, {@code SahBuilder.build(boxes, triangles)}): {@code mesh().reordered(order)} as it
     * would have been, its material ids following {@code order}, its vertices numbered by first use
     * and their values copied there. This mesh is spent: its triangle array, renumbered, is the
     * result's, and its positions' blocks are let go.
     */
    public Mesh afterTrianglesMoved(int[] order) {
        if (order.length != triangleCount()) {
            throw new IllegalArgumentException("need one entry per triangle, got " + order.length + " for " + triangleCount());
        }
        int[] newIndex = new int[vertices];
        Arrays.fill(newIndex, -1);
        int used = 0;
        for (int i = 0; i < triangles.length; i++) {
            int v = triangles[i];
            if (newIndex[v] < 0) {
                newIndex[v] = used++;
            }
            triangles[i] = newIndex[v];
        }
        for (int v = 0; v < vertices; v++) {
            if (newIndex[v] < 0) {
                newIndex[v] = used++; // no triangle uses it: last, as reordered puts it
            }
        }
        int[] ids = null;
        if (materialIds != null) {
            ids = new int[materialIds.length];
            for (int k = 0; k < order.length; k++) {
                ids[k] = materialIds[order[k]];
            }
        }
        double[] p = new double[3 * vertices];
        for (int v = 0; v < vertices; v++) {
            // read in file order, written where the vertex goes: every write independent of the others
            int to = 3 * newIndex[v];
            p[to] = positions.get(3 * v);
            p[to + 1] = positions.get(3 * v + 1);
            p[to + 2] = positions.get(3 * v + 2);
        }
        positions.clear(); // its blocks are garbage from now on, whoever still holds this mesh
        return new Mesh(p, scatter(normals, 3, newIndex), scatter(uvs, 2, newIndex), triangles, ids);
    }

    /** Per-vertex values, {@code width} each, vertex v's moved to place {@code newIndex[v]}; null stays null. */
    private static float[] scatter(float[] values, int width, int[] newIndex) {
        if (values == null) {
            return null;
        }
        float[] out = new float[values.length];
        for (int v = 0; v < newIndex.length; v++) {
            System.arraycopy(values, width * v, out, width * newIndex[v], width);
        }
        return out;
    }

    @Override
    public String toString() {
        return "ParsedMesh[" + vertices + " vertices, " + triangleCount() + " triangles]";
    }
}

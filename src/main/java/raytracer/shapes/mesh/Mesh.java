package raytracer.shapes.mesh;

import java.util.Arrays;
import raytracer.math.BBox;

/**
 * Indexed triangle data in flat arrays. Every corner of a triangle is one vertex index into
 * {@code positions} (x, y, z per vertex) and, when present, {@code normals} (x, y, z per vertex) and
 * {@code uvs} (u, v per vertex). {@code materialIds} gives each triangle an index into a material
 * list kept by whoever made the mesh, or is null when all share one material. The loaders make
 * a {@link ParsedMesh} first, which becomes a mesh in its BVH's leaf order.
 */
public final class Mesh {
    private final double[] positions;
    private final float[] normals;
    private final float[] uvs;
    private final int[] triangles;
    private final int[] materialIds;

    public Mesh(double[] positions, float[] normals, float[] uvs, int[] triangles, int[] materialIds) {
        checkArrays(positions.length, normals, uvs, triangles, materialIds);
        this.positions = positions;
        this.normals = normals;
        this.uvs = uvs;
        this.triangles = triangles;
        this.materialIds = materialIds;
    }

    /**
     * Checks that the arrays of a mesh of {@code positionCount} coordinates fit together: threes, one
     * normal and (u, v) per vertex, one material id per triangle, every index a vertex. Returns the
     * number of vertices.
     */
    static int checkArrays(long positionCount, float[] normals, float[] uvs, int[] triangles, int[] materialIds) {
        if (positionCount % 3 != 0 || triangles.length % 3 != 0) {
            throw new IllegalArgumentException("positions and triangles come in threes");
        }
        int vertices = Math.toIntExact(positionCount / 3);
        if (normals != null && normals.length != 3L * vertices) {
            throw new IllegalArgumentException("need one normal per vertex");
        }
        if (uvs != null && uvs.length != 2L * vertices) {
            throw new IllegalArgumentException("need one (u, v) per vertex");
        }
        if (materialIds != null && materialIds.length != triangles.length / 3) {
            throw new IllegalArgumentException("need one material id per triangle");
        }
        for (int index : triangles) {
            if (index < 0 || index >= vertices) {
                throw new IllegalArgumentException("vertex index " + index + " out of range 0.." + (vertices - 1));
            }
        }
        return vertices;
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    /** Offset into {@link #positions()} of corner {@code k} (0, 1, 2) of triangle {@code tri}. */
    public int corner(int tri, int k) {
        return 3 * triangles[3 * tri + k];
    }

    /** The vertex index of corner {@code k} of triangle {@code tri}. */
    public int vertex(int tri, int k) {
        return triangles[3 * tri + k];
    }

    /** The vertex indices of all triangles, three each (not a copy: read only). */
    public int[] triangles() {
        return triangles;
    }

    public double[] positions() {
        return positions;
    }

    public boolean hasNormals() {
        return normals != null;
    }

    public boolean hasUvs() {
        return uvs != null;
    }

    public float[] normals() {
        return normals;
    }

    public float[] uvs() {
        return uvs;
    }

    public int[] materialIds() {
        return materialIds;
    }

    /**
     * The same mesh with its triangles in another order and its vertices renumbered in order of
     * first use: triangle k of the result is triangle {@code order[k]} of this one, with its
     * material id, and the vertices of a run of triangles lie together in memory (vertices no
     * triangle uses go last). Positions, normals and texture coordinates are copied in the new
     * order; every triangle keeps its corners' values.
     */
    public Mesh reordered(int[] order) {
        if (order.length != triangleCount()) {
            throw new IllegalArgumentException("need one entry per triangle, got " + order.length + " for " + triangleCount());
        }
        int[] newIndex = new int[vertexCount()];
        Arrays.fill(newIndex, -1);
        int[] oldIndex = new int[vertexCount()];
        int used = 0;
        int[] renumbered = new int[triangles.length];
        for (int k = 0; k < order.length; k++) {
            for (int corner = 0; corner < 3; corner++) {
                int v = triangles[3 * order[k] + corner];
                if (newIndex[v] < 0) {
                    newIndex[v] = used;
                    oldIndex[used++] = v;
                }
                renumbered[3 * k + corner] = newIndex[v];
            }
        }
        for (int v = 0; v < vertexCount(); v++) {
            if (newIndex[v] < 0) {
                oldIndex[used++] = v;
            }
        }
        int[] ids = null;
        if (materialIds != null) {
            ids = new int[materialIds.length];
            for (int k = 0; k < order.length; k++) {
                ids[k] = materialIds[order[k]];
            }
        }
        double[] p = new double[positions.length];
        for (int v = 0; v < oldIndex.length; v++) {
            System.arraycopy(positions, 3 * oldIndex[v], p, 3 * v, 3);
        }
        return new Mesh(p, gather(normals, 3, oldIndex), gather(uvs, 2, oldIndex), renumbered, ids);
    }

    /** Per-vertex values, {@code width} each, in the order of {@code oldIndex}; null stays null. */
    private static float[] gather(float[] values, int width, int[] oldIndex) {
        if (values == null) {
            return null;
        }
        float[] out = new float[values.length];
        for (int v = 0; v < oldIndex.length; v++) {
            System.arraycopy(values, width * oldIndex[v], out, width * v, width);
        }
        return out;
    }

    public BBox bounds() {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int i = 0; i < positions.length; i++) {
            lo[i % 3] = Math.min(lo[i % 3], positions[i]);
            hi[i % 3] = Math.max(hi[i % 3], positions[i]);
        }
        return new BBox(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    }

    @Override
    public String toString() {
        return "Mesh[" + vertexCount() + " vertices, " + triangleCount() + " triangles"
               + (normals != null ? ", normals" : "") + (uvs != null ? ", uvs" : "")
               + (materialIds != null ? ", materials " + Arrays.stream(materialIds).distinct().count() : "") + "]";
    }
}

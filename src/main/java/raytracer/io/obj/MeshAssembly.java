package raytracer.io.obj;

import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.SmoothNormals;

/**
 * Turns the parsed corner triples into a {@link Mesh}: as is when corners are positions only,
 * otherwise one mesh vertex per distinct (v, vt, vn) triple, found with an open-addressing table
 * over int keys (no object per corner).
 */
final class MeshAssembly {
    private MeshAssembly() {
    }

    static Mesh build(ObjLoader parsed, boolean smoothNormals) {
        double[] positions = parsed.positions().toArray();
        int[] v = parsed.cornerV().toArray();
        int[] materialIds = parsed.materialIds();
        Buffers.Ints vtCorners = parsed.cornerVt();
        Buffers.Ints vnCorners = parsed.cornerVn();
        if (vtCorners == null && vnCorners == null) {
            float[] normals = smoothNormals ? SmoothNormals.angleWeighted(positions, v) : null;
            return new Mesh(positions, normals, null, v, materialIds);
        }
        int[] vt = vtCorners != null ? vtCorners.toArray() : null;
        int[] vn = vnCorners != null ? vnCorners.toArray() : null;
        float[] texcoords = parsed.texcoords().data;
        float[] fileNormals = parsed.normals().data;

        int corners = v.length;
        int capacity = Integer.highestOneBit(Math.max(16, corners * 2)) * 2;
        int[] keys = new int[3 * capacity];
        int[] slotVertex = new int[capacity];
        java.util.Arrays.fill(slotVertex, -1);
        int[] triangles = new int[corners];
        Buffers.Doubles outPositions = new Buffers.Doubles();
        Buffers.Floats outUvs = vt != null ? new Buffers.Floats() : null;
        Buffers.Floats outNormals = vn != null ? new Buffers.Floats() : null;
        int next = 0;
        for (int c = 0; c < corners; c++) {
            int a = v[c];
            int b = vt != null ? vt[c] : -1;
            int n = vn != null ? vn[c] : -1;
            int slot = (int) (((a * 0x9E3779B1L) ^ (b * 0x85EBCA77L) ^ (n * 0xC2B2AE3DL)) & (capacity - 1));
            while (slotVertex[slot] >= 0 && !(keys[3 * slot] == a && keys[3 * slot + 1] == b && keys[3 * slot + 2] == n)) {
                slot = (slot + 1) & (capacity - 1);
            }
            if (slotVertex[slot] < 0) {
                keys[3 * slot] = a;
                keys[3 * slot + 1] = b;
                keys[3 * slot + 2] = n;
                slotVertex[slot] = next++;
                for (int k = 0; k < 3; k++) {
                    outPositions.add(positions[3 * a + k]);
                }
                if (outUvs != null) {
                    outUvs.add(b >= 0 ? texcoords[2 * b] : 0f);
                    outUvs.add(b >= 0 ? texcoords[2 * b + 1] : 0f);
                }
                if (outNormals != null) {
                    for (int k = 0; k < 3; k++) {
                        // a corner without vn in a file that has them: zero, the renderer then uses the face normal
                        outNormals.add(n >= 0 ? fileNormals[3 * n + k] : 0f);
                    }
                }
            }
            triangles[c] = slotVertex[slot];
        }
        double[] p = outPositions.toArray();
        float[] normals = outNormals != null ? java.util.Arrays.copyOf(outNormals.data, outNormals.size)
                        : smoothNormals ? SmoothNormals.angleWeighted(p, triangles) : null;
        float[] uvs = outUvs != null ? java.util.Arrays.copyOf(outUvs.data, outUvs.size) : null;
        return new Mesh(p, normals, uvs, triangles, materialIds);
    }
}

package raytracer.shapes.mesh;

/**
 * Vertex normals for a mesh that has none: each triangle adds its unit normal weighted by its
 * angle at the vertex (Thürmer and Wüthrich, "Computing vertex normals from polygonal facets",
 * 1998), which, unlike area weighting, does not depend on how a surface is cut into triangles.
 */
public final class SmoothNormals {
    private SmoothNormals() {
    }

    /** One unit normal per vertex of the positions {@code p} (x, y, z each), for the triangles' vertex indices. */
    public static float[] angleWeighted(Growing.Doubles positions, int[] triangles) {
        // the corners of a triangle, three at a time: a flat copy of the positions would be the
        // mesh's size again, its blocks read through an index are not much slower
        double[] p = new double[9];
        double[] sum = new double[positions.size()];
        for (int t = 0; t < triangles.length; t += 3) {
            for (int k = 0; k < 3; k++) {
                for (int d = 0; d < 3; d++) {
                    p[3 * k + d] = positions.get(3 * triangles[t + k] + d);
                }
            }
            int a = 0;
            int b = 3;
            int c = 6;
            double[] n = cross(p, a, b, c);
            double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (!(len > 0)) {
                continue; // a degenerate triangle has no direction to give
            }
            int[] corners = {a, b, c};
            for (int k = 0; k < 3; k++) {
                double angle = angle(p, corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]);
                int vertex = 3 * triangles[t + k];
                for (int d = 0; d < 3; d++) {
                    sum[vertex + d] += angle * n[d] / len;
                }
            }
        }
        float[] normals = new float[sum.length];
        for (int i = 0; i < sum.length; i += 3) {
            double len = Math.sqrt(sum[i] * sum[i] + sum[i + 1] * sum[i + 1] + sum[i + 2] * sum[i + 2]);
            if (len > 0) {
                for (int d = 0; d < 3; d++) {
                    normals[i + d] = (float) (sum[i + d] / len);
                }
            }
        }
        return normals;
    }

    private static double[] cross(double[] p, int a, int b, int c) {
        double e1x = p[b] - p[a];
        double e1y = p[b + 1] - p[a + 1];
        double e1z = p[b + 2] - p[a + 2];
        double e2x = p[c] - p[a];
        double e2y = p[c + 1] - p[a + 1];
        double e2z = p[c + 2] - p[a + 2];
        return new double[] {e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x};
    }

    /** The angle at vertex a between the edges to b and c. */
    private static double angle(double[] p, int a, int b, int c) {
        double ux = p[b] - p[a];
        double uy = p[b + 1] - p[a + 1];
        double uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a];
        double vy = p[c + 1] - p[a + 1];
        double vz = p[c + 2] - p[a + 2];
        double cross = Math.sqrt(Math.pow(uy * vz - uz * vy, 2) + Math.pow(uz * vx - ux * vz, 2) + Math.pow(ux * vy - uy * vx, 2));
        return Math.atan2(cross, ux * vx + uy * vy + uz * vz);
    }
}

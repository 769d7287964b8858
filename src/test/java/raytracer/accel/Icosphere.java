package raytracer.accel;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import raytracer.shapes.mesh.Mesh;

/** A closed triangle mesh: an icosahedron subdivided n times, vertices pushed onto the unit sphere. */
final class Icosphere {
    private Icosphere() {
    }

    static Mesh make(int subdivisions) {
        double t = (1 + Math.sqrt(5)) / 2;
        double[] p = {-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t,
                      t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1};
        int[] f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6,
                   7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
        for (int i = 0; i < p.length; i += 3) {
            normalize(p, i);
        }
        for (int s = 0; s < subdivisions; s++) {
            Map<Long, Integer> midpoints = new HashMap<>();
            int[] next = new int[f.length * 4];
            double[][] grow = {Arrays.copyOf(p, p.length * 4)};
            int[] count = {p.length / 3};
            for (int i = 0; i < f.length; i += 3) {
                int a = f[i];
                int b = f[i + 1];
                int c = f[i + 2];
                int ab = midpoint(a, b, grow, count, midpoints);
                int bc = midpoint(b, c, grow, count, midpoints);
                int ca = midpoint(c, a, grow, count, midpoints);
                int[] four = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
                System.arraycopy(four, 0, next, 4 * i, 12);
            }
            f = next;
            p = Arrays.copyOf(grow[0], 3 * count[0]);
        }
        return new Mesh(p, null, null, f, null);
    }

    private static int midpoint(int a, int b, double[][] p, int[] count, Map<Long, Integer> cache) {
        long key = Math.min(a, b) * 1_000_000L + Math.max(a, b);
        Integer known = cache.get(key);
        if (known != null) {
            return known;
        }
        int m = count[0]++;
        for (int k = 0; k < 3; k++) {
            p[0][3 * m + k] = 0.5 * (p[0][3 * a + k] + p[0][3 * b + k]);
        }
        normalize(p[0], 3 * m);
        cache.put(key, m);
        return m;
    }

    private static void normalize(double[] p, int i) {
        double len = Math.sqrt(p[i] * p[i] + p[i + 1] * p[i + 1] + p[i + 2] * p[i + 2]);
        p[i] /= len;
        p[i + 1] /= len;
        p[i + 2] /= len;
    }
}

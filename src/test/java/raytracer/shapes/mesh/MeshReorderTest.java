package raytracer.shapes.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A parse is put in its tree's leaf order without a copy of its triangles: the median
 * builder moves the triangle array with the boxes, and {@link ParsedMesh#afterTrianglesMoved} does
 * the rest. The result must be {@link Mesh#reordered}'s (checked by TriangleMeshTest), value for value,
 * whatever the permutation and whichever attributes the mesh has.
 */
class MeshReorderTest {
    @Test
    void afterTheTrianglesMovedTheMeshIsTheCopysOrder() {
        Random random = new Random(26);
        for (int trial = 0; trial < 200; trial++) {
            int vertices = 1 + random.nextInt(trial < 100 ? 12 : 3000);
            int triangles = 1 + random.nextInt(trial < 100 ? 10 : 5000);
            double[] p = new double[3 * vertices];
            for (int i = 0; i < p.length; i++) {
                p[i] = random.nextGaussian();
            }
            float[] n = random.nextBoolean() ? floats(random, 3 * vertices) : null;
            float[] uv = random.nextBoolean() ? floats(random, 2 * vertices) : null;
            int[] t = new int[3 * triangles];
            for (int i = 0; i < t.length; i++) {
                t[i] = random.nextInt(vertices); // some vertices unused, some triangles degenerate
            }
            int[] ids = null;
            if (random.nextBoolean()) {
                ids = new int[triangles];
                for (int i = 0; i < triangles; i++) {
                    ids[i] = random.nextInt(5);
                }
            }
            int[] order = permutation(random, triangles);
            Mesh copied = new Mesh(p, n, uv, t, ids).reordered(order);
            // what the builder does to the triangle array it carries
            int[] moved = new int[t.length];
            for (int k = 0; k < triangles; k++) {
                System.arraycopy(t, 3 * order[k], moved, 3 * k, 3);
            }
            Growing.Doubles growing = new Growing.Doubles();
            growing.addAll(p, p.length);
            ParsedMesh spent = new ParsedMesh(growing, n, uv, moved, ids);
            Mesh after = spent.afterTrianglesMoved(order);
            assertSame(moved, after.triangles(), "the triangle array is taken over, not copied");
            assertArrayEquals(copied.positions(), after.positions(), 0);
            assertArrayEquals(copied.normals(), after.normals());
            assertArrayEquals(copied.uvs(), after.uvs());
            assertArrayEquals(copied.triangles(), after.triangles());
            assertArrayEquals(copied.materialIds(), after.materialIds());
        }
    }

    @Test
    void anOrderOfAnotherLengthIsRefused() {
        Growing.Doubles p = new Growing.Doubles();
        p.addAll(new double[9], 9);
        ParsedMesh mesh = new ParsedMesh(p, null, null, new int[] {0, 1, 2, 0, 1, 2}, null);
        assertThrows(IllegalArgumentException.class, () -> mesh.afterTrianglesMoved(new int[] {0}));
    }

    private static float[] floats(Random random, int n) {
        float[] f = new float[n];
        for (int i = 0; i < n; i++) {
            f[i] = random.nextFloat();
        }
        return f;
    }

    private static int[] permutation(Random random, int n) {
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        for (int i = n - 1; i > 0; i--) {
            int j = random.nextInt(i + 1);
            int swap = order[i];
            order[i] = order[j];
            order[j] = swap;
        }
        return order;
    }
}

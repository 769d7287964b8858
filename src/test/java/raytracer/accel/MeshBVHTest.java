package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.core.ShadeRec;
import raytracer.materials.Matte;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.shapes.Watertight;
import raytracer.shapes.mesh.Mesh;

class MeshBVHTest {

    private static MeshBVH build(Mesh mesh, String builder) {
        FlatBVH bvh = builder.equals("sah") ? new SahBuilder(4).build(MeshBVH.triangleBounds(mesh))
                                            : new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(mesh));
        return new MeshBVH(mesh, bvh, List.of());
    }

    /** A soup of random triangles of mixed sizes, overlapping, some degenerate. */
    static Mesh soup(int n, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] p = new double[9 * n];
        int[] f = new int[3 * n];
        for (int t = 0; t < n; t++) {
            double size = Math.pow(10, r.nextDouble(-3, 0));
            double cx = r.nextDouble(-1, 1);
            double cy = r.nextDouble(-1, 1);
            double cz = r.nextDouble(-1, 1);
            for (int k = 0; k < 9; k++) {
                p[9 * t + k] = (k % 3 == 0 ? cx : k % 3 == 1 ? cy : cz) + size * r.nextDouble(-1, 1);
            }
            if (t % 50 == 0) {
                System.arraycopy(p, 9 * t, p, 9 * t + 3, 3); // a degenerate one
            }
            f[3 * t] = 3 * t;
            f[3 * t + 1] = 3 * t + 1;
            f[3 * t + 2] = 3 * t + 2;
        }
        return new Mesh(p, null, null, f, null);
    }

    @ParameterizedTest
    @ValueSource(strings = {"median", "sah"})
    void closestHitAndAnyHitAgreeWithBruteForce(String builder) {
        Mesh mesh = soup(3000, 11);
        MeshBVH bvh = build(mesh, builder);
        ShadeRec sr = BvhTesting.shadeRec();
        ShadeRec brute = BvhTesting.shadeRec();
        SplittableRandom r = new SplittableRandom(5);
        Ray ray = new Ray();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            ray.set(r.nextDouble(-2, 2), r.nextDouble(-2, 2), r.nextDouble(-2, 2),
                    r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1));
            double best = Double.POSITIVE_INFINITY;
            int bestTri = -1;
            for (int t = 0; t < mesh.triangleCount(); t++) {
                double d = Watertight.intersect(ray, mesh.positions(), mesh.corner(t, 0), mesh.corner(t, 1),
                                                mesh.corner(t, 2), best, brute);
                if (d < best) {
                    best = d;
                    bestTri = t;
                }
            }
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            boolean hit = bvh.hit(ray, sr);
            assertEquals(bestTri >= 0, hit, "ray " + i);
            assertEquals(hit, bvh.shadowHit(ray, Double.POSITIVE_INFINITY, sr));
            if (hit) {
                hits++;
                assertEquals(best, sr.t, 0, "closest distance, ray " + i);
                assertEquals(bestTri, sr.primitive);
                // a shadow ray stopping just short of the closest hit finds nothing
                assertEquals(false, bvh.shadowHit(ray, Math.nextDown(best), sr));
            }
        }
        assertTrue(hits > 2000, "enough rays should hit to mean something: " + hits);
    }

    @ParameterizedTest
    @ValueSource(strings = {"median", "sah"})
    void bvhIsWellFormed(String builder) {
        Mesh mesh = soup(5000, 3);
        FlatBVH bvh = build(mesh, builder).bvh();
        boolean[] seen = new boolean[mesh.triangleCount()];
        for (int k : bvh.order) {
            seen[k] = true;
        }
        for (boolean s : seen) {
            assertTrue(s, "every triangle appears in the leaf order");
        }
        assertTrue(bvh.depth() < FlatBVH.MAX_DEPTH);
        // every node's box contains its children's boxes, and every leaf's box its triangles' boxes
        double[] triangles = MeshBVH.triangleBounds(mesh);
        float[] root = new float[6];
        for (int k = 0; k < 6; k++) {
            root[k] = (float) bvh.rootBound(k);
        }
        int leaves = checkContains(bvh, root, bvh.rootLink, bvh.rootCount, triangles);
        assertEquals(bvh.nodeCount(), 2 * leaves - 1, "a binary tree has one leaf more than interior nodes");
    }

    /** Checks the subtree under a child entry (link, count) with box {@code box}; returns its leaves. */
    private static int checkContains(FlatBVH bvh, float[] box, int link, int count, double[] triangles) {
        if (count > 0) {
            for (int i = link; i < link + count; i++) {
                int t = bvh.order[i];
                for (int k = 0; k < 3; k++) {
                    assertTrue(box[k] <= triangles[6 * t + k], "leaf box below triangle " + t);
                    assertTrue(box[3 + k] >= triangles[6 * t + 3 + k], "leaf box above triangle " + t);
                }
            }
            return 1;
        }
        int leaves = 0;
        for (int side = 0; side < 2; side++) {
            int r = FlatBVH.RECORD * link;
            float[] child = new float[6];
            for (int k = 0; k < 6; k++) {
                child[k] = Float.intBitsToFloat(bvh.records[r + (side == 0 ? FlatBVH.LEFT_BOX : FlatBVH.RIGHT_BOX) + k]);
            }
            for (int k = 0; k < 3; k++) {
                assertTrue(box[k] <= child[k]);
                assertTrue(box[3 + k] >= child[3 + k]);
            }
            leaves += checkContains(bvh, child, bvh.records[r + FlatBVH.LINK + side], bvh.records[r + FlatBVH.COUNT + side],
                                    triangles);
        }
        return leaves;
    }

    /**
     * A direction component of -0.0 has 1/d = -infinity; choosing the near slab by the sign of d
     * (false for -0.0) put the entry distance at +infinity and culled every box.
     */
    @ParameterizedTest
    @ValueSource(strings = {"median", "sah"})
    void raysWithNegativeZeroDirectionsFindTheMesh(String builder) {
        Mesh mesh = soup(500, 7);
        MeshBVH bvh = build(mesh, builder);
        ShadeRec sr = BvhTesting.shadeRec();
        Ray ray = new Ray();
        int hits = 0;
        for (int i = 0; i < 400; i++) {
            double x = -1 + i / 200.0;
            ray.set(x, 0.3, -3, 0.0, 0.0, 1);
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            boolean hit = bvh.hit(ray, sr);
            double t = sr.t;
            ray.set(x, 0.3, -3, -0.0, -0.0, 1);
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            assertEquals(hit, bvh.hit(ray, sr), "closest hit with -0.0 components, x = " + x);
            assertEquals(t, sr.t, 0);
            assertEquals(hit, bvh.shadowHit(ray, Double.POSITIVE_INFINITY, sr), "any hit with -0.0 components, x = " + x);
            hits += hit ? 1 : 0;
        }
        assertTrue(hits > 50, "enough rays should hit to mean something: " + hits);
    }

    @Test
    void theClosestHitInterpolatesNormalsAndUvsAndPicksItsMaterial() {
        // two triangles, a and b, one above the other; rays from above see b's (material 1) first
        double[] p = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 1, 2, 0, 1, 0, 2, 1};
        float s = (float) Math.sqrt(0.5);
        float[] n = {0, 0, 1, s, 0, s, 0, s, s, 0, 0, 1, s, 0, s, 0, s, s};
        float[] uv = {0.1f, 0.2f, 0.9f, 0.3f, 0.4f, 0.8f, 0.1f, 0.2f, 0.9f, 0.3f, 0.4f, 0.8f};
        Mesh mesh = new Mesh(p, n, uv, new int[] {0, 1, 2, 3, 4, 5}, new int[] {0, 1});
        Matte first = new Matte(0, 1, RGBColor.WHITE);
        Matte second = new Matte(0, 1, RGBColor.gray(0.5));
        MeshBVH bvh = new MeshBVH(mesh, new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(mesh)), List.of(first, second));
        ShadeRec sr = BvhTesting.shadeRec();
        SplittableRandom r = new SplittableRandom(9);
        Ray ray = new Ray();
        for (int i = 0; i < 1000; i++) {
            double b1 = r.nextDouble(0, 0.5);
            double b2 = r.nextDouble(0, 0.5);
            double b0 = 1 - b1 - b2;
            ray.set(2 * b1, 2 * b2, 5, 0, 0, -1);
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            assertTrue(bvh.hit(ray, sr));
            sr.complete(ray);
            assertEquals(4, sr.t, 1e-12);
            assertEquals(1, sr.primitive, "the upper triangle");
            assertSame(second, sr.material, "material id 1");
            double nx = b1 * s;
            double ny = b2 * s;
            double nz = b0 + (b1 + b2) * s;
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            assertEquals(nx / len, sr.normal.x, 1e-6, "normal x, ray " + i);
            assertEquals(ny / len, sr.normal.y, 1e-6, "normal y, ray " + i);
            assertEquals(nz / len, sr.normal.z, 1e-6, "normal z, ray " + i);
            assertEquals(1, sr.geometricNormal.z, 1e-12, "the face normal stays the face's");
            assertEquals(b0 * 0.1 + b1 * 0.9 + b2 * 0.4, sr.u, 1e-6, "u, ray " + i);
            assertEquals(b0 * 0.2 + b1 * 0.3 + b2 * 0.8, sr.v, 1e-6, "v, ray " + i);
        }
        // from below, the lower triangle (material 0) faces away: normals turn to the viewer
        ray.set(0.5, 0.5, -5, 0, 0, 1);
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        assertTrue(bvh.hit(ray, sr));
        sr.complete(ray);
        assertEquals(0, sr.primitive);
        assertSame(first, sr.material);
        assertFalse(sr.frontFace);
        assertTrue(sr.normal.z < 0 && sr.geometricNormal.z < 0, "both normals face the ray's origin");
    }
}

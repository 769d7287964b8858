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
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.materials.Matte;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.ShearedRay;
import raytracer.math.MutableVec3;
import raytracer.shapes.Watertight;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.TriangleMesh;

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
            ShearedRay sheared = new ShearedRay().load(ray);
            for (int t = 0; t < mesh.triangleCount(); t++) {
                double d = Watertight.intersect(sheared, mesh.positions(), mesh.corner(t, 0), mesh.corner(t, 1),
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
                assertEquals(bestTri, bvh.bvh().order[sr.primitive], "the triangle, in the mesh's own numbering");
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
        int leaves = checkContains(bvh, bvh.rootBox, 0, bvh.rootLink, bvh.rootCount, triangles);
        assertEquals(bvh.nodeCount(), 2 * leaves - 1, "a binary tree has one leaf more than interior nodes");
    }

    /** Checks the subtree of a child (link, count) whose box is {@code box[at .. at + 6)}; returns its leaves. */
    private static int checkContains(FlatBVH bvh, float[] box, int at, int link, int count, double[] triangles) {
        if (count > 0) {
            for (int i = link; i < link + count; i++) {
                int t = bvh.order[i];
                for (int k = 0; k < 3; k++) {
                    assertTrue(box[at + k] <= triangles[6 * t + k], "leaf box below triangle " + t);
                    assertTrue(box[at + 3 + k] >= triangles[6 * t + 3 + k], "leaf box above triangle " + t);
                }
            }
            return 1;
        }
        int leaves = 0;
        BvhNodes nodes = bvh.nodes;
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            int child = BvhNodes.boxAt(link, side);
            for (int k = 0; k < 3; k++) {
                assertTrue(box[at + k] <= nodes.bounds[child + k]);
                assertTrue(box[at + 3 + k] >= nodes.bounds[child + 3 + k]);
            }
            leaves += checkContains(bvh, nodes.bounds, child, nodes.link(link, side), nodes.primitiveCount(link, side),
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

    /**
     * The BVH renumbers the mesh's triangles in its leaf order; completed through it, a hit must
     * be the one the plain mesh completes: the same point, normals, u/v and material.
     */
    @Test
    void hitsCompleteAsOnThePlainMesh() {
        Mesh sphere = Icosphere.make(3);
        int n = sphere.triangleCount();
        int[] ids = new int[n];
        float[] uv = new float[2 * sphere.vertexCount()];
        float[] normals = new float[3 * sphere.vertexCount()];
        for (int t = 0; t < n; t++) {
            ids[t] = t % 3;
        }
        double[] p = sphere.positions();
        for (int v = 0; v < sphere.vertexCount(); v++) {
            uv[2 * v] = (float) p[3 * v];
            uv[2 * v + 1] = (float) p[3 * v + 2];
            for (int k = 0; k < 3; k++) {
                normals[3 * v + k] = (float) p[3 * v + k];
            }
        }
        Mesh mesh = new Mesh(p, normals, uv, sphere.triangles(), ids);
        List<Material> materials = List.of(new Matte(0, 1, RGBColor.WHITE), new Matte(0, 1, RGBColor.gray(0.5)),
                                           new Matte(0, 1, RGBColor.gray(0.2)));
        MeshBVH bvh = new MeshBVH(mesh, new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(mesh)), materials);
        TriangleMesh plain = new TriangleMesh(mesh, materials);
        ShadeRec a = BvhTesting.shadeRec();
        ShadeRec b = BvhTesting.shadeRec();
        SplittableRandom r = new SplittableRandom(13);
        Ray ray = new Ray();
        for (int i = 0; i < 2000; i++) {
            ray.set(r.nextDouble(-3, 3), r.nextDouble(-3, 3), 4, r.nextDouble(-0.5, 0.5), r.nextDouble(-0.5, 0.5), -1);
            a.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            b.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            boolean hit = plain.hit(ray, a);
            assertEquals(hit, bvh.hit(ray, b), "ray " + i);
            if (!hit) {
                continue;
            }
            a.complete(ray);
            b.complete(ray);
            assertEquals(a.t, b.t, 0);
            assertEquals(a.primitive, bvh.bvh().order[b.primitive], "the same triangle");
            assertSame(a.material, b.material, "ray " + i);
            assertEquals(a.u, b.u, 0);
            assertEquals(a.v, b.v, 0);
            assertEqualVectors(a.hitPoint, b.hitPoint, "hit point, ray " + i);
            assertEqualVectors(a.normal, b.normal, "normal, ray " + i);
            assertEqualVectors(a.geometricNormal, b.geometricNormal, "geometric normal, ray " + i);
        }
    }

    private static void assertEqualVectors(MutableVec3 expected, MutableVec3 actual, String what) {
        assertEquals(expected.x, actual.x, 0, what);
        assertEquals(expected.y, actual.y, 0, what);
        assertEquals(expected.z, actual.z, 0, what);
    }
}

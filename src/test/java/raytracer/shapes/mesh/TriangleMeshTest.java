package raytracer.shapes.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.materials.Matte;
import raytracer.math.RGBColor;
import raytracer.math.Ray;

/** A mesh on its own, without a BVH: every triangle tested, and the winner completed. */
class TriangleMeshTest {

    @Test
    void theClosestHitInterpolatesNormalsAndUvsAndPicksItsMaterial() {
        // two triangles, a and b, one above the other; rays from above see b's (material 1) first
        double[] p = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 1, 2, 0, 1, 0, 2, 1};
        float s = (float) Math.sqrt(0.5);
        float[] n = {0, 0, 1, s, 0, s, 0, s, s, 0, 0, 1, s, 0, s, 0, s, s};
        float[] uv = {0.1f, 0.2f, 0.9f, 0.3f, 0.4f, 0.8f, 0.1f, 0.2f, 0.9f, 0.3f, 0.4f, 0.8f};
        Mesh data = new Mesh(p, n, uv, new int[] {0, 1, 2, 3, 4, 5}, new int[] {0, 1});
        Matte first = new Matte(0, 1, RGBColor.WHITE);
        Matte second = new Matte(0, 1, RGBColor.gray(0.5));
        TriangleMesh mesh = new TriangleMesh(data, List.of(first, second));
        ShadeRec sr = MeshTesting.shadeRec();
        SplittableRandom r = new SplittableRandom(9);
        Ray ray = new Ray();
        for (int i = 0; i < 1000; i++) {
            double b1 = r.nextDouble(0, 0.5);
            double b2 = r.nextDouble(0, 0.5);
            double b0 = 1 - b1 - b2;
            ray.set(2 * b1, 2 * b2, 5, 0, 0, -1);
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            assertTrue(mesh.hit(ray, sr));
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
            // a shadow ray that stops short of the upper triangle is not blocked; one that goes past it is
            assertFalse(mesh.shadowHit(ray, 3.99, sr));
            assertTrue(mesh.shadowHit(ray, 4.01, sr));
        }
        // from below, the lower triangle (material 0) faces away: normals turn to the viewer
        ray.set(0.5, 0.5, -5, 0, 0, 1);
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        assertTrue(mesh.hit(ray, sr));
        sr.complete(ray);
        assertEquals(0, sr.primitive);
        assertSame(first, sr.material);
        assertFalse(sr.frontFace);
        assertTrue(sr.normal.z < 0 && sr.geometricNormal.z < 0, "both normals face the ray's origin");
    }

    /**
     * Four triangles over six vertices (vertex 5 unused), put in the order 2, 0, 3, 1: the
     * vertices are renumbered by first use, and every triangle keeps its corners' positions,
     * normals, texture coordinates and material.
     */
    @Test
    void reorderingRenumbersTrianglesAndVerticesAndKeepsWhatEachCornerHolds() {
        double[] p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 2, 0, 9, 9, 9};
        float[] n = new float[18];
        float[] uv = new float[12];
        for (int v = 0; v < 6; v++) {
            n[3 * v + 2] = v; // each vertex's normal and uv say which vertex it was
            uv[2 * v] = v;
            uv[2 * v + 1] = 10 + v;
        }
        int[] triangles = {0, 1, 2, 1, 3, 2, 3, 4, 2, 0, 4, 1};
        int[] ids = {7, 8, 9, 6};
        Mesh mesh = new Mesh(p, n, uv, triangles, ids);
        int[] order = {2, 0, 3, 1};
        Mesh reordered = mesh.reordered(order);
        // first use: old 3, 4, 2 of triangle 2, then 0, 1 of triangle 0; 5 is last
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 2, 3, 1, 4, 4, 0, 2}, reordered.triangles());
        assertArrayEquals(new int[] {9, 7, 6, 8}, reordered.materialIds());
        for (int k = 0; k < 4; k++) {
            for (int corner = 0; corner < 3; corner++) {
                int was = mesh.vertex(order[k], corner);
                int is = reordered.vertex(k, corner);
                for (int axis = 0; axis < 3; axis++) {
                    assertEquals(p[3 * was + axis], reordered.positions()[3 * is + axis]);
                }
                assertEquals(was, reordered.normals()[3 * is + 2]);
                assertEquals(was, reordered.uvs()[2 * is]);
                assertEquals(10 + was, reordered.uvs()[2 * is + 1]);
            }
        }
        assertEquals(9, reordered.positions()[3 * 5], "the unused vertex goes last");
        assertArrayEquals(new int[] {0, 1, 2, 1, 3, 2, 3, 4, 2, 0, 4, 1}, mesh.triangles(), "the original is unchanged");
    }

    @Test
    void grazingRaysHitTheFaceTheyComeFromAndRaysInThePlaneMiss() {
        // a quad on the plane z = x / 2, normal (-1, 0, 2) / sqrt5, split along its diagonal
        TriangleMesh quad = new TriangleMesh(new Mesh(new double[] {0, 0, 0, 2, 0, 1, 2, 2, 1, 0, 2, 0}, null, null,
                                                      new int[] {0, 1, 2, 0, 2, 3}, null), List.of());
        double[] n = {-1 / Math.sqrt(5), 0, 2 / Math.sqrt(5)};
        double[] a = {0, 1, 0};
        ShadeRec sr = MeshTesting.shadeRec();
        Ray ray = new Ray();
        // inside one triangle, and on the diagonal the two share
        for (double[] q : new double[][] {{1.5, 0.5, 0.75}, {1, 1, 0.5}}) {
            for (double slope : new double[] {1e-2, 1e-6, 1e-10, 1e-14}) {
                for (int side : new int[] {1, -1}) {
                    double[] d = {a[0] - side * slope * n[0], a[1] - side * slope * n[1], a[2] - side * slope * n[2]};
                    ray.set(q[0] - d[0], q[1] - d[1], q[2] - d[2], d[0], d[1], d[2]);
                    sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                    String what = "at " + q[0] + ", " + q[1] + ", slope " + slope + " from the " + (side > 0 ? "front" : "back");
                    boolean hit = quad.hit(ray, sr);
                    if (!hit && slope < 1e-10) {
                        // the start lies within 1e-14 of the plane: within the test's bound on t of
                        // it, where a ray starting on the plane must not find it (Watertight)
                        continue;
                    }
                    assertTrue(hit, what);
                    sr.complete(ray);
                    assertEquals(side > 0, sr.frontFace, what);
                    assertTrue(sr.geometricNormal.dot(d[0], d[1], d[2]) < 0, what + ": the normal faces the ray");
                }
            }
            ray.set(q[0] - 1, q[1] - 1, q[2] - 0.5, 1, 1, 0.5);
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            assertFalse(quad.hit(ray, sr), "a ray in the plane");
            assertFalse(quad.shadowHit(ray, Double.POSITIVE_INFINITY, sr), "a shadow ray in the plane");
        }
    }
}

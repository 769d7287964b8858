package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Ray;
import raytracer.shapes.mesh.Mesh;

/**
 * Watertightness (Woop, Benthin and Wald 2013): rays aimed exactly at the vertices and at points of
 * the shared edges of a closed mesh must never slip through it. Two million rays, zero misses.
 * Each ray comes from within 80 degrees of the outward direction at its target, so every face
 * around the target faces it: a ray that grazes the silhouette may rightly miss by rounding, a
 * ray that enters through an edge may not.
 */
class WatertightTest {
    private static final int RAYS = 2_000_000;

    @Test
    void raysAtEdgesAndVerticesOfAClosedMeshNeverSlipThrough() {
        Mesh mesh = Icosphere.make(3);
        assertEquals(1280, mesh.triangleCount());
        double[] bounds = MeshBVH.triangleBounds(mesh);
        MeshBVH bvh = new MeshBVH(mesh, new MedianSplitBuilder(4).build(bounds), List.of());
        ShadeRec sr = BvhTesting.shadeRec();
        SplittableRandom r = new SplittableRandom(2013);
        double[] p = mesh.positions();
        Ray ray = new Ray();
        int misses = 0;
        int shadowMisses = 0;
        for (int i = 0; i < RAYS; i++) {
            int tri = r.nextInt(mesh.triangleCount());
            int a = mesh.corner(tri, r.nextInt(3));
            int b = mesh.corner(tri, r.nextInt(3));
            // half of the targets are vertices (a == b or s == 0), the others points on an edge
            double s = r.nextBoolean() ? 0 : r.nextDouble();
            double tx = p[a] + s * (p[b] - p[a]);
            double ty = p[a + 1] + s * (p[b + 1] - p[a + 1]);
            double tz = p[a + 2] + s * (p[b + 2] - p[a + 2]);
            // from 0.5 to 100 units away, within 80 degrees of the outward (radial) direction
            double[] w = coneDirection(tx, ty, tz, Math.cos(Math.toRadians(80)), r);
            double dist = 0.5 + 99.5 * r.nextDouble();
            double ox = tx + dist * w[0];
            double oy = ty + dist * w[1];
            double oz = tz + dist * w[2];
            ray.set(ox, oy, oz, tx - ox, ty - oy, tz - oz);
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            if (!bvh.hit(ray, sr) || sr.t > 1 + 1e-9) {
                misses++;
            }
            if (!bvh.shadowHit(ray, 2, sr)) {
                shadowMisses++;
            }
        }
        assertEquals(0, misses, "closest-hit rays that slipped through an edge or vertex");
        assertEquals(0, shadowMisses, "shadow rays that slipped through an edge or vertex");
    }

    /**
     * Exact ties: a closed cube [0,4]^3 tiled by unit squares (two triangles each), hit through every
     * grid vertex and edge midpoint by rays whose edge functions come out exactly zero. A test that
     * treats zero as outside, on either side of the edge, loses these rays.
     */
    @Test
    void raysThroughExactGridVerticesAndEdgesOfAClosedCubeAllHit() {
        Mesh cube = gridCube(4);
        MeshBVH bvh = new MeshBVH(cube, new SahBuilder(4).build(MeshBVH.triangleBounds(cube)), List.of());
        ShadeRec sr = BvhTesting.shadeRec();
        Ray ray = new Ray();
        double[][] slants = {{0, 0}, {0.5, 0}, {0, 0.5}, {0.25, -0.5}, {-1, 1}};
        int rays = 0;
        int misses = 0;
        for (int axis = 0; axis < 3; axis++) {
            for (int side = 0; side < 2; side++) {
                double normal = side == 0 ? -1 : 1;
                for (int i = 0; i <= 8; i++) {
                    for (int j = 0; j <= 8; j++) {
                        for (double[] slant : slants) {
                            double[] target = new double[3];
                            target[axis] = side == 0 ? 0 : 4;
                            target[(axis + 1) % 3] = 0.5 * i;
                            target[(axis + 2) % 3] = 0.5 * j;
                            double[] d = new double[3];
                            d[axis] = -normal;
                            d[(axis + 1) % 3] = slant[0];
                            d[(axis + 2) % 3] = slant[1];
                            ray.set(target[0] - 8 * d[0], target[1] - 8 * d[1], target[2] - 8 * d[2], d[0], d[1], d[2]);
                            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                            rays++;
                            if (!bvh.hit(ray, sr) || sr.t > 8) {
                                misses++;
                            }
                        }
                    }
                }
            }
        }
        assertEquals(6 * 81 * 5, rays);
        assertEquals(0, misses, "rays through exact vertices or edges that found no triangle");
    }

    private static Mesh gridCube(int n) {
        java.util.List<double[]> vertices = new java.util.ArrayList<>();
        java.util.Map<String, Integer> index = new java.util.HashMap<>();
        java.util.List<Integer> faces = new java.util.ArrayList<>();
        for (int axis = 0; axis < 3; axis++) {
            for (int side = 0; side < 2; side++) {
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        int[] quad = new int[4];
                        int[][] corners = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                        for (int c = 0; c < 4; c++) {
                            double[] v = new double[3];
                            v[axis] = side * n;
                            v[(axis + 1) % 3] = corners[c][0];
                            v[(axis + 2) % 3] = corners[c][1];
                            String key = v[0] + "," + v[1] + "," + v[2];
                            quad[c] = index.computeIfAbsent(key, k -> {
                                vertices.add(v);
                                return vertices.size() - 1;
                            });
                        }
                        // split alternately along both diagonals, so ties occur on both kinds of edge
                        int[] tris = (i + j) % 2 == 0 ? new int[] {0, 1, 2, 0, 2, 3} : new int[] {0, 1, 3, 1, 2, 3};
                        for (int t : tris) {
                            faces.add(quad[t]);
                        }
                    }
                }
            }
        }
        double[] p = new double[3 * vertices.size()];
        for (int v = 0; v < vertices.size(); v++) {
            System.arraycopy(vertices.get(v), 0, p, 3 * v, 3);
        }
        return new Mesh(p, null, null, faces.stream().mapToInt(Integer::intValue).toArray(), null);
    }

    /** A uniformly random unit vector within the cone cos(angle) >= cosMax around (ax, ay, az). */
    private static double[] coneDirection(double ax, double ay, double az, double cosMax, SplittableRandom r) {
        double len = Math.sqrt(ax * ax + ay * ay + az * az);
        ax /= len;
        ay /= len;
        az /= len;
        double[] d = new double[3];
        double dot;
        do {
            double x = r.nextDouble(-1, 1);
            double y = r.nextDouble(-1, 1);
            double z = r.nextDouble(-1, 1);
            double l = Math.sqrt(x * x + y * y + z * z);
            if (l > 1 || l == 0) {
                dot = -2;
                continue;
            }
            d[0] = x / l;
            d[1] = y / l;
            d[2] = z / l;
            dot = d[0] * ax + d[1] * ay + d[2] * az;
        } while (dot < cosMax);
        return d;
    }
}

package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.PropertyCheck.forAll;
import static raytracer.PropertyCheck.logUniform;
import static raytracer.PropertyCheck.unitVector;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Matrix4;
import raytracer.math.Ray;
import raytracer.shapes.mesh.Mesh;

/**
 * Closed meshes never leak, at any scale and distance from the origin: a ray from inside always
 * hits, a ray from outside aimed at an inside point hits before reaching it, and a ray aimed at a
 * vertex or a point of an edge from the side that edge faces hits it. Each try builds an icosphere
 * (1 to 3 subdivisions) or a cube, scaled by 1e-4 to 1e6, turned and moved up to 1e4 sizes away,
 * with a median or an SAH tree, and shoots 25 rays; closest hit and any hit (shadow rays) both.
 * The vertices are moved before the tree is built, so the mesh itself holds the coordinates.
 */
class ClosedMeshPropertiesTest {
    private static final int TRIES = 200;
    private static final int RAYS = 25;
    /** The meshes in their own frames, made once: icospheres of 1, 2 and 3 subdivisions, the cube. */
    private static final Mesh[] ICOSPHERES = {Icosphere.make(1), Icosphere.make(2), Icosphere.make(3)};
    private static final Mesh CUBE = Placed.cube();

    @Test
    void raysFromInsideAlwaysHit() {
        forAll("rays from inside a closed mesh hit it", TRIES, random -> {
            Placed m = Placed.random(random);
            ShadeRec sr = BvhTesting.shadeRec();
            Ray ray = new Ray();
            for (int i = 0; i < RAYS; i++) {
                double[] o = m.toWorld(m.insidePoint(random));
                double[] d = unitVector(random);
                ray.set(o[0], o[1], o[2], d[0], d[1], d[2]);
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                assertTrue(m.bvh.hit(ray, sr) && sr.t > 0 && sr.t < Double.POSITIVE_INFINITY, m + ": closest hit from " + m.describe(o));
                assertTrue(m.bvh.shadowHit(ray, Double.POSITIVE_INFINITY, sr), m + ": any hit from " + m.describe(o));
            }
        });
    }

    @Test
    void raysAimedInsideFromOutsideHitBeforeTheirTarget() {
        forAll("rays aimed inside a closed mesh from outside hit it", TRIES, random -> {
            Placed m = Placed.random(random);
            ShadeRec sr = BvhTesting.shadeRec();
            Ray ray = new Ray();
            for (int i = 0; i < RAYS; i++) {
                double[] target = m.toWorld(m.insidePoint(random));
                double[] away = unitVector(random);
                double distance = logUniform(random, 2, 1000);
                double[] o = m.toWorld(new double[] {distance * away[0], distance * away[1], distance * away[2]});
                // t = 1 at the target
                ray.set(o[0], o[1], o[2], target[0] - o[0], target[1] - o[1], target[2] - o[2]);
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                assertTrue(m.bvh.hit(ray, sr) && sr.t < 1, m + ": closest hit from " + m.describe(o));
                assertTrue(m.bvh.shadowHit(ray, 1, sr), m + ": any hit from " + m.describe(o));
            }
        });
    }

    /**
     * Aimed exactly at a vertex or edge point of an icosphere, from within 80 degrees of the outward
     * normal of every face that holds the target (so all of them face the ray: a ray grazing the
     * silhouette could rightly miss), the ray must find a triangle no further than the target.
     */
    @Test
    void raysAimedAtEdgesAndVerticesNeverSlipThrough() {
        forAll("rays at edges and vertices of an icosphere hit it", TRIES, random -> {
            Placed m = Placed.randomIcosphere(random);
            ShadeRec sr = BvhTesting.shadeRec();
            Ray ray = new Ray();
            double[] p = m.mesh.positions();
            double cos80 = Math.cos(Math.toRadians(80));
            for (int i = 0; i < RAYS; i++) {
                int tri = random.nextInt(m.mesh.triangleCount());
                int a = m.mesh.corner(tri, random.nextInt(3));
                int b = m.mesh.corner(tri, random.nextInt(3));
                double s = random.nextBoolean() ? 0 : random.nextDouble();
                double[] target = {p[a] + s * (p[b] - p[a]), p[a + 1] + s * (p[b + 1] - p[a + 1]), p[a + 2] + s * (p[b + 2] - p[a + 2])};
                double[][] normals = m.faceNormals(a, s == 0 ? a : b);
                double[] w;
                do {
                    w = unitVector(random);
                } while (!facesAll(w, normals, cos80));
                double distance = m.scale * logUniform(random, 0.5, 100);
                double[] o = {target[0] + distance * w[0], target[1] + distance * w[1], target[2] + distance * w[2]};
                ray.set(o[0], o[1], o[2], target[0] - o[0], target[1] - o[1], target[2] - o[2]);
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                // the target itself is rounded onto the edge, so allow the last few ulps of t
                assertTrue(m.bvh.hit(ray, sr) && sr.t <= 1 + 1e-9, m + ": closest hit at " + m.describe(target));
                assertTrue(m.bvh.shadowHit(ray, 2, sr), m + ": any hit at " + m.describe(target));
            }
        });
    }

    private static boolean facesAll(double[] w, double[][] normals, double minCos) {
        for (double[] n : normals) {
            if (w[0] * n[0] + w[1] * n[1] + w[2] * n[2] < minCos) {
                return false;
            }
        }
        return true;
    }

    /** A closed mesh in its own frame, placed by a random similarity transform, with its tree. */
    private static final class Placed {
        final Mesh mesh;
        final MeshBVH bvh;
        final Matrix4 transform;
        final double scale;
        final boolean cube;
        final String name;

        private Placed(Mesh local, boolean cube, Matrix4 transform, double scale, boolean sah, String name) {
            this.transform = transform;
            this.scale = scale;
            this.cube = cube;
            double[] p = local.positions().clone();
            for (int i = 0; i < p.length; i += 3) {
                double[] w = apply(transform, p[i], p[i + 1], p[i + 2]);
                System.arraycopy(w, 0, p, i, 3);
            }
            this.mesh = new Mesh(p, null, null, local.triangles(), null);
            FlatBVH tree = sah ? new SahBuilder(4).build(MeshBVH.triangleBounds(mesh))
                               : new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(mesh));
            this.bvh = new MeshBVH(mesh, tree, List.of());
            this.name = name + (sah ? ", SAH" : ", median") + String.format(", scale %.3g", scale);
        }

        static Placed random(SplittableRandom random) {
            return random.nextBoolean() ? randomIcosphere(random) : place(CUBE, true, random, "cube");
        }

        static Placed randomIcosphere(SplittableRandom random) {
            int n = random.nextInt(3);
            return place(ICOSPHERES[n], false, random, "icosphere " + (n + 1));
        }

        private static Placed place(Mesh local, boolean cube, SplittableRandom random, String name) {
            double scale = logUniform(random, 1e-4, 1e6);
            double[] axis = unitVector(random);
            double far = random.nextBoolean() ? 0 : logUniform(random, 1, 1e4) * scale;
            double[] shift = unitVector(random);
            Matrix4 t = Matrix4.translate(far * shift[0], far * shift[1], far * shift[2])
                .multiply(Matrix4.scale(scale, scale, scale))
                .multiply(Matrix4.rotateY(Math.toDegrees(Math.atan2(axis[0], axis[2]))))
                .multiply(Matrix4.rotateX(random.nextDouble(-180, 180)))
                .multiply(Matrix4.rotateZ(random.nextDouble(-180, 180)));
            return new Placed(local, cube, t, scale, random.nextBoolean(), name);
        }

        /** A point at least 5% of the size inside: the icosphere holds the ball of radius 0.79. */
        double[] insidePoint(SplittableRandom random) {
            if (cube) {
                return new double[] {random.nextDouble(-0.95, 0.95), random.nextDouble(-0.95, 0.95), random.nextDouble(-0.95, 0.95)};
            }
            double[] d = unitVector(random);
            double r = 0.74 * Math.cbrt(random.nextDouble());
            return new double[] {r * d[0], r * d[1], r * d[2]};
        }

        double[] toWorld(double[] local) {
            return apply(transform, local[0], local[1], local[2]);
        }

        /** Unit outward normals of the faces holding vertices a and b (a vertex when a == b). */
        double[][] faceNormals(int a, int b) {
            java.util.List<double[]> normals = new java.util.ArrayList<>();
            double[] p = mesh.positions();
            double[] c = toWorld(new double[3]);
            for (int tri = 0; tri < mesh.triangleCount(); tri++) {
                boolean hasA = false;
                boolean hasB = false;
                for (int k = 0; k < 3; k++) {
                    hasA |= mesh.corner(tri, k) == a;
                    hasB |= mesh.corner(tri, k) == b;
                }
                if (hasA && hasB) {
                    int i = mesh.corner(tri, 0);
                    int j = mesh.corner(tri, 1);
                    int k = mesh.corner(tri, 2);
                    double ux = p[j] - p[i];
                    double uy = p[j + 1] - p[i + 1];
                    double uz = p[j + 2] - p[i + 2];
                    double vx = p[k] - p[i];
                    double vy = p[k + 1] - p[i + 1];
                    double vz = p[k + 2] - p[i + 2];
                    double[] n = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
                    double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                    // outward: away from the centre
                    double sign = n[0] * (p[i] - c[0]) + n[1] * (p[i + 1] - c[1]) + n[2] * (p[i + 2] - c[2]) > 0 ? 1 : -1;
                    normals.add(new double[] {sign * n[0] / len, sign * n[1] / len, sign * n[2] / len});
                }
            }
            return normals.toArray(new double[0][]);
        }

        String describe(double[] p) {
            return String.format("(%.17g, %.17g, %.17g)", p[0], p[1], p[2]);
        }

        @Override
        public String toString() {
            return name;
        }

        private static double[] apply(Matrix4 m, double x, double y, double z) {
            return new double[] {
                m.get(0, 0) * x + m.get(0, 1) * y + m.get(0, 2) * z + m.get(0, 3),
                m.get(1, 0) * x + m.get(1, 1) * y + m.get(1, 2) * z + m.get(1, 3),
                m.get(2, 0) * x + m.get(2, 1) * y + m.get(2, 2) * z + m.get(2, 3)};
        }

        /** The cube [-1, 1]^3, two triangles a face, wound outwards, corners shared. */
        static Mesh cube() {
            double[] p = new double[24];
            for (int i = 0; i < 8; i++) {
                p[3 * i] = (i & 1) == 0 ? -1 : 1;
                p[3 * i + 1] = (i & 2) == 0 ? -1 : 1;
                p[3 * i + 2] = (i & 4) == 0 ? -1 : 1;
            }
            int[] f = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
            return new Mesh(p, null, null, f, null);
        }
    }
}

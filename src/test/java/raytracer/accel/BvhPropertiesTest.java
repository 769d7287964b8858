package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.PropertyCheck.forAll;
import static raytracer.PropertyCheck.logUniform;
import static raytracer.PropertyCheck.unitVector;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.ShearedRay;
import raytracer.shapes.Box;
import raytracer.shapes.Instance;
import raytracer.shapes.Sphere;
import raytracer.shapes.Watertight;
import raytracer.shapes.mesh.Mesh;

/**
 * A BVH is only a faster way to find what a search of every primitive finds: for random scenes
 * (1 to 400 primitives of sizes over three decades, the whole scene scaled by 1e-4 to 1e6 and moved
 * up to 1e4 of its sizes from the origin) and random rays, the closest hit of the median and the SAH
 * trees has the same distance, bit for bit, and the same primitive as the brute-force search (the
 * same intersection routine on the same numbers), and any-hit agrees for rays of limited length.
 * Half the rays are aimed at a point of a random primitive, so hits are common.
 */
class BvhPropertiesTest {
    private static final int TRIES = 200;
    private static final int RAYS = 40;

    @Test
    void meshTreesFindWhatAllTrianglesFind() {
        forAll("mesh BVH closest and any hit equal brute force", TRIES, random -> {
            Frame f = Frame.random(random);
            int n = 1 + random.nextInt(400);
            double[] p = new double[9 * n];
            int[] tris = new int[3 * n];
            for (int i = 0; i < n; i++) {
                double[] c = f.point(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double size = f.scale * logUniform(random, 1e-3, 1);
                for (int k = 0; k < 3; k++) {
                    double[] d = unitVector(random);
                    for (int a = 0; a < 3; a++) {
                        p[9 * i + 3 * k + a] = c[a] + size * d[a];
                    }
                    tris[3 * i + k] = 3 * i + k;
                }
            }
            Mesh mesh = new Mesh(p, null, null, tris, null);
            boolean sah = random.nextBoolean();
            MeshBVH bvh = new MeshBVH(mesh, sah ? new SahBuilder(1 + random.nextInt(8)).build(MeshBVH.triangleBounds(mesh))
                                                : new MedianSplitBuilder(1 + random.nextInt(8)).build(MeshBVH.triangleBoxes(mesh)),
                                      List.of());
            ShadeRec sr = BvhTesting.shadeRec();
            ShadeRec brute = BvhTesting.shadeRec();
            Ray ray = new Ray();
            for (int r = 0; r < RAYS; r++) {
                int aim = 3 * random.nextInt(n);
                double b = random.nextDouble();
                double c = random.nextDouble() * (1 - b);
                double[] target = {p[3 * aim] + b * (p[3 * aim + 3] - p[3 * aim]) + c * (p[3 * aim + 6] - p[3 * aim]),
                                   p[3 * aim + 1] + b * (p[3 * aim + 4] - p[3 * aim + 1]) + c * (p[3 * aim + 7] - p[3 * aim + 1]),
                                   p[3 * aim + 2] + b * (p[3 * aim + 5] - p[3 * aim + 2]) + c * (p[3 * aim + 8] - p[3 * aim + 2])};
                f.randomRay(random, target, ray);
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                boolean hit = bvh.hit(ray, sr);
                ShearedRay sheared = new ShearedRay().load(ray);
                double best = Double.POSITIVE_INFINITY;
                int bestTriangle = -1;
                for (int i = 0; i < n; i++) {
                    double t = Watertight.intersect(sheared, p, 3 * tris[3 * i], 3 * tris[3 * i + 1], 3 * tris[3 * i + 2], best, brute);
                    if (t < best) {
                        best = t;
                        bestTriangle = i;
                    }
                }
                String what = (sah ? "SAH" : "median") + " tree of " + n + " triangles, ray " + r;
                assertEquals(bestTriangle >= 0, hit, what + ": hit or miss");
                if (hit) {
                    assertEquals(best, sr.t, 0, what + ": closest distance");
                    // sr.primitive numbers the triangles in the tree's leaf order, as the tree's own mesh does
                    double[] lp = bvh.mesh().positions();
                    int[] lt = bvh.mesh().triangles();
                    double own = Watertight.intersect(sheared, lp, 3 * lt[3 * sr.primitive], 3 * lt[3 * sr.primitive + 1],
                                                      3 * lt[3 * sr.primitive + 2], Double.POSITIVE_INFINITY, brute);
                    assertEquals(best, own, 0, what + ": the triangle it names lies at that distance");
                }
                double tMax = hit ? sr.t * random.nextDouble(0.5, 1.5) : Double.POSITIVE_INFINITY;
                assertEquals(best < tMax, bvh.shadowHit(ray, tMax, sr), what + ": any hit before " + tMax);
            }
        });
    }

    @Test
    void objectTreesFindWhatAllObjectsFind() {
        forAll("object BVH closest and any hit equal brute force", TRIES, random -> {
            Frame f = Frame.random(random);
            int n = 1 + random.nextInt(300);
            List<GeometricObject> objects = new ArrayList<>();
            List<double[]> centres = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                double[] c = f.point(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
                double size = f.scale * logUniform(random, 1e-3, 0.3);
                GeometricObject o = switch (random.nextInt(3)) {
                    case 0 -> new Sphere(new Point3D(c[0], c[1], c[2]), size);
                    case 1 -> new Box(new Point3D(c[0] - size, c[1] - size, c[2] - size), new Point3D(c[0] + size, c[1] + size, c[2] + size));
                    default -> new Instance(new Box(new Point3D(-size, -size / 2, -size / 3), new Point3D(size, size / 2, size / 3)),
                                            Matrix4.translate(c[0], c[1], c[2]).multiply(Matrix4.rotateY(random.nextDouble(360)))
                                                .multiply(Matrix4.rotateX(random.nextDouble(360))));
                };
                o.setCastsShadows(random.nextInt(5) != 0);
                objects.add(o);
                centres.add(c);
            }
            boolean sah = random.nextBoolean();
            ObjectBVH bvh = ObjectBVH.build(objects, sah);
            ShadeRec sr = BvhTesting.shadeRec();
            ShadeRec brute = BvhTesting.shadeRec();
            Ray ray = new Ray();
            for (int r = 0; r < RAYS; r++) {
                f.randomRay(random, centres.get(random.nextInt(n)), ray);
                brute.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                for (GeometricObject o : objects) {
                    o.hit(ray, brute);
                }
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                boolean hit = bvh.hit(ray, sr);
                String what = (sah ? "SAH" : "median") + " tree of " + n + " objects, ray " + r;
                assertEquals(brute.hitAnObject(), hit, what + ": hit or miss");
                double tMax = Double.POSITIVE_INFINITY;
                if (hit) {
                    assertEquals(brute.t, sr.t, 0, what + ": closest distance");
                    assertSame(brute.object, sr.object, what + ": closest object");
                    tMax = sr.t * random.nextDouble(0.5, 1.5);
                }
                boolean blocked = false;
                for (GeometricObject o : objects) {
                    blocked |= o.castsShadows() && o.shadowHit(ray, tMax, brute);
                }
                assertEquals(blocked, bvh.shadowHit(ray, tMax, sr), what + ": any hit before " + tMax);
            }
        });
    }

    /** Where a random scene lives: scaled by 1e-4 to 1e6, half the time far from the origin. */
    private record Frame(double scale, double[] offset) {
        static Frame random(SplittableRandom random) {
            double scale = logUniform(random, 1e-4, 1e6);
            double far = random.nextBoolean() ? 0 : scale * logUniform(random, 1, 1e4);
            double[] d = unitVector(random);
            return new Frame(scale, new double[] {far * d[0], far * d[1], far * d[2]});
        }

        double[] point(double x, double y, double z) {
            return new double[] {offset[0] + scale * x, offset[1] + scale * y, offset[2] + scale * z};
        }

        /** From a random point of the scene's neighbourhood: half aimed at {@code target}, half anywhere. */
        void randomRay(SplittableRandom random, double[] target, Ray ray) {
            double[] o = point(random.nextDouble(-3, 3), random.nextDouble(-3, 3), random.nextDouble(-3, 3));
            double[] d = random.nextBoolean() ? new double[] {target[0] - o[0], target[1] - o[1], target[2] - o[2]} : unitVector(random);
            assertTrue(d[0] != 0 || d[1] != 0 || d[2] != 0);
            ray.set(o[0], o[1], o[2], d[0], d[1], d[2]);
        }
    }
}

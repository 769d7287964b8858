package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.BiFunction;
import java.util.function.Predicate;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.PropertyCheck;
import raytracer.accel.MedianSplitBuilder;
import raytracer.accel.MeshBVH;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.HalfSpace;
import raytracer.math.Matrix4;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.TriangleMesh;

/**
 * A shadow ray aimed at a point q of a surface (a light's point lying in a ceiling, on a wall, on
 * a box's face) ends on that surface: the surface touches the ray's end and must not block it,
 * whatever the shape, its scale (1e-4 to 1e6), its distance from the origin (up to 1e6) and the
 * ray's angle (a lamp flush with its ceiling lit the floor with 2% of its light). The
 * ray is made as the renderer makes it ({@link ShadeRec#spawnRayTo}) from a point o off the
 * surface, on its outside for closed shapes, at least 5 degrees from grazing. Three checks:
 * <ul>
 * <li>where q lies exactly on the surface, the ray is not blocked;</li>
 * <li>where the surface, in exact arithmetic ({@link BigDecimal}) on the ray as stored, meets the
 * ray at t &gt;= 1 (q rounded to a point just short of a tilted surface), it is not blocked: the
 * bound that spares the end covers the test's rounding;</li>
 * <li>aimed a millionth of the distance beyond q, the ray crosses the surface before its end and
 * must be blocked: the bound is not loose.</li>
 * </ul>
 */
class ShadowRayEndsTest {
    private final HitTesting testing = new HitTesting();

    /**
     * A surface with a point q on it (exactly when {@code exact}, else within rounding), the unit
     * normal there, a point well inside the surface near q for the ray that crosses it (q itself
     * unless q is a vertex), and the exact test of whether the ray, as stored, meets the surface
     * before t = 1.
     */
    record Surface(GeometricObject object, double[] q, double[] inside, double[] n, boolean closed, boolean exact,
                   Predicate<Ray> crossesBeforeEnd) {
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"plane", "tilted plane", "rectangle", "disk", "tilted disk", "triangle", "tilted triangle",
                            "mesh", "box", "cylinder cap", "cylinder side", "sphere", "instanced box"})
    void aSurfaceThroughTheRaysEndDoesNotBlockIt(String shape) {
        BiFunction<SplittableRandom, double[], Surface> make = surfaces(shape);
        int[] beyondEnd = new int[1];
        PropertyCheck.forAll("a surface through the end of a shadow ray: " + shape, 3_000, random -> {
            double scale = PropertyCheck.logUniform(random, 1e-4, 1e6);
            double offset = random.nextInt(3) == 0 ? 0 : PropertyCheck.logUniform(random, 1, 1e6) * (random.nextBoolean() ? 1 : -1);
            Surface s = make.apply(random, new double[] {scale, offset});
            double[] w = PropertyCheck.unitVector(random);
            double cos = w[0] * s.n[0] + w[1] * s.n[1] + w[2] * s.n[2];
            if (Math.abs(cos) < 0.09 || s.closed && cos < 0) {
                return; // too close to grazing, or inside a solid
            }
            double reach = scale * PropertyCheck.logUniform(random, 0.05, 20);
            double[] o = {s.q[0] + reach * w[0], s.q[1] + reach * w[1], s.q[2] + reach * w[2]};
            Ray toQ = aim(o, s.q);
            boolean blocked = testing.shadowHit(s.object, toQ, 1);
            if (s.exact) {
                assertFalse(blocked, () -> "blocked by the surface at its end: " + toQ);
            }
            if (!s.crossesBeforeEnd.test(toQ)) {
                assertFalse(blocked, () -> "blocked, where in exact arithmetic the surface lies at or beyond the end: " + toQ);
                beyondEnd[0]++;
            }
            // a millionth of the distance beyond, and at least 2^-43 of the coordinates' size (rounding is 2^-53 of it)
            double[] g = s.inside;
            double distance = Math.sqrt((g[0] - o[0]) * (g[0] - o[0]) + (g[1] - o[1]) * (g[1] - o[1]) + (g[2] - o[2]) * (g[2] - o[2]));
            double size = Math.max(Math.abs(g[0]), Math.max(Math.abs(g[1]), Math.abs(g[2])));
            double push = (1e-6 * distance + 0x1.0p-43 * size) / distance;
            double[] beyond = new double[3];
            for (int k = 0; k < 3; k++) {
                beyond[k] = g[k] + push * (g[k] - o[k]);
            }
            Ray past = aim(o, beyond);
            assertTrue(testing.shadowHit(s.object, past, 1), () -> "not blocked by a surface it crosses: " + past);
        });
        assertTrue(beyondEnd[0] > 300, "only " + beyondEnd[0] + " rays ended short of the surface in exact arithmetic");
    }

    /** The renderer's shadow ray from o (an exact point: no error bound) to q. */
    private Ray aim(double[] o, double[] q) {
        ShadeRec sr = testing.record();
        sr.hitPoint.set(o[0], o[1], o[2]);
        sr.hitError.set(0, 0, 0);
        sr.geometricNormal.set(q[0] - o[0], q[1] - o[1], q[2] - o[2]).normalize();
        return sr.spawnRayTo(q[0], q[1], q[2], new Ray());
    }

    private static BiFunction<SplittableRandom, double[], Surface> surfaces(String shape) {
        return (random, so) -> {
            double s = so[0];
            double d = so[1];
            // a level that is a coordinate of the scene: 0, the offset, or the offset plus a few units
            double level = random.nextInt(3) == 0 ? 0 : d + s * random.nextInt(-3, 4);
            double x = d + s * random.nextDouble(-1, 1);
            double z = d + s * random.nextDouble(-1, 1);
            double[] q = {x, level, z};
            double[] up = {0, 1, 0};
            Predicate<Ray> level0 = ray -> Exact.planeBeforeEnd(ray, new double[] {0, level, 0}, up);
            switch (shape) {
                case "plane":
                    return flat(new Plane(new Point3D(d, level, d), new Normal(0, 1, 0)), q, up, level0);
                case "tilted plane": {
                    // through a point p near q: q, rounded, lies within rounding of the plane, on either side
                    double[] n = PropertyCheck.unitVector(random);
                    Vector3D e = new Vector3D(n[0], n[1], n[2]).cross(new Vector3D(random.nextDouble(-1, 1), 1, random.nextDouble(-1, 1)));
                    Point3D p = new Point3D(x, level, z).add(e.scale(s * random.nextDouble(-2, 2)));
                    Plane plane = new Plane(p, new Normal(n[0], n[1], n[2]));
                    HalfSpace stored = plane.wholePlane();
                    double[] normal = {stored.nx(), stored.ny(), stored.nz()};
                    return new Surface(plane, q, q, normal, false, false,
                                       ray -> Exact.planeBeforeEnd(ray, new double[] {p.x(), p.y(), p.z()}, normal));
                }
                case "rectangle": {
                    double angle = random.nextDouble(2 * Math.PI);
                    Vector3D a = new Vector3D(Math.cos(angle), 0, Math.sin(angle)).scale(4 * s);
                    Vector3D b = new Vector3D(-Math.sin(angle), 0, Math.cos(angle)).scale(4 * s);
                    Point3D corner = new Point3D(x, level, z).add(a.scale(-0.5)).add(b.scale(-0.5));
                    return flat(new Rectangle(new Point3D(corner.x(), level, corner.z()), a, b), q, up, level0);
                }
                case "disk":
                    return flat(new Disk(new Point3D(d, level, d), new Vector3D(0, 1, 0), 3 * s), q, up, level0);
                case "tilted disk": {
                    double[] n = PropertyCheck.unitVector(random);
                    Vector3D stored = new Vector3D(n[0], n[1], n[2]).normalize();
                    double[] normal = {stored.x(), stored.y(), stored.z()};
                    Vector3D e = stored.cross(new Vector3D(random.nextDouble(-1, 1), 1, random.nextDouble(-1, 1))).normalize();
                    Point3D center = new Point3D(x, level, z).add(e.scale(s * random.nextDouble(-0.5, 0.5)));
                    return new Surface(new Disk(center, stored, s), q, q, normal, false, false,
                                       ray -> Exact.planeBeforeEnd(ray, new double[] {center.x(), center.y(), center.z()}, normal));
                }
                case "triangle":
                    return flat(new Triangle(new Point3D(d - 5 * s, level, d - 5 * s), new Point3D(d + 5 * s, level, d - 5 * s),
                                             new Point3D(d, level, d + 5 * s)), q, up, level0);
                case "tilted triangle": {
                    // q a point of its inside, rounded: within rounding of the plane, on either side
                    Point3D a = new Point3D(x, level, z);
                    Point3D b = a.add(new Vector3D(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1)).scale(s));
                    Point3D c = a.add(new Vector3D(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1)).scale(s));
                    double[] inside = {(a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3, (a.z() + b.z() + c.z()) / 3};
                    Vector3D n = b.sub(a).cross(c.sub(a)).normalize();
                    double[][] v = {{a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}, {c.x(), c.y(), c.z()}};
                    return new Surface(new Triangle(a, b, c), inside, inside, new double[] {n.x(), n.y(), n.z()}, false, false,
                                       ray -> Exact.triangleBeforeEnd(ray, v));
                }
                case "mesh": {
                    double[] p = {d - 5 * s, level, d - 5 * s, d + 5 * s, level, d - 5 * s, d + 5 * s, level, d + 5 * s,
                                  d - 5 * s, level, d + 5 * s};
                    Mesh mesh = new Mesh(p, null, null, new int[] {0, 3, 2, 0, 2, 1}, null);
                    GeometricObject object = random.nextBoolean() ? new TriangleMesh(mesh, List.<Material>of())
                        : new MeshBVH(mesh, new MedianSplitBuilder(1).build(MeshBVH.triangleBoxes(mesh)), List.<Material>of());
                    return flat(object, q, up, level0);
                }
                case "box":
                    return new Surface(new Box(new Point3D(d - 4 * s, level - 2 * s, d - 4 * s), new Point3D(d + 4 * s, level, d + 4 * s)),
                                       q, q, up, true, true, level0);
                case "cylinder cap": {
                    // in its own coordinates, around the y axis: the scene's offset is left out
                    double[] onCap = {s * random.nextDouble(-1, 1), level, s * random.nextDouble(-1, 1)};
                    return new Surface(new Cylinder(level - 2 * s - Math.abs(d), level, 3 * s, true), onCap, onCap, up, true, true, level0);
                }
                case "cylinder side": {
                    // a radius 5 2^k with the point (3, y, 4) 2^k on it, so that x^2 + z^2 = r^2 exactly;
                    // from inside its tangent plane a chord would cross first, so the ray comes from outside
                    double unit = Math.scalb(1.0, Math.getExponent(s));
                    double y = level + s * random.nextDouble(-1, 1);
                    double[] onSide = {3 * unit, y, 4 * unit};
                    return new Surface(new Cylinder(y - 3 * s, y + 3 * s, 5 * unit, false), onSide, onSide, new double[] {0.6, 0, 0.8},
                                       true, true, ray -> Exact.endInside(ray, new double[] {0, 0, 0}, 5 * unit, true));
                }
                case "sphere": {
                    // q = c + r n, rounded: within rounding of the sphere, on either side
                    double[] n = PropertyCheck.unitVector(random);
                    double r = s * random.nextDouble(0.5, 3);
                    double[] onSphere = {x + r * n[0], level + r * n[1], z + r * n[2]};
                    return new Surface(new Sphere(new Point3D(x, level, z), r), onSphere, onSphere, n, true, false,
                                       ray -> Exact.endInside(ray, new double[] {x, level, z}, r, false));
                }
                case "instanced box": {
                    // a box of half-size 1, scaled by 2s, turned about y and moved: in exact arithmetic
                    // its top face lies at ty + 2s, since the matrix's second row is (0, 2s, 0, ty)
                    Box box = new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1));
                    double ty = level - 2 * s;
                    Matrix4 toWorld = Matrix4.translate(x, ty, z).multiply(Matrix4.rotateY(random.nextDouble(360)))
                                             .multiply(Matrix4.scale(2 * s, 2 * s, 2 * s));
                    double[] onTop = {x, ty + 2 * s, z};
                    return new Surface(new Instance(box, toWorld), onTop, onTop, up, true, false,
                                       ray -> Exact.planeBeforeEnd(ray, new double[] {0, ty, 0}, new double[] {0, 1, 0}, 2 * s));
                }
                default:
                    throw new IllegalArgumentException(shape);
            }
        };
    }

    /** A flat surface in the plane y = level, q exactly on it. */
    private static Surface flat(GeometricObject object, double[] q, double[] up, Predicate<Ray> level) {
        return new Surface(object, q, q, up, false, true, level);
    }

    /** Where the ray as stored meets a surface, in exact arithmetic. */
    private static final class Exact {
        private static BigDecimal big(double v) {
            return new BigDecimal(v);
        }

        private static BigDecimal dot(BigDecimal[] a, BigDecimal[] b) {
            return a[0].multiply(b[0]).add(a[1].multiply(b[1])).add(a[2].multiply(b[2]));
        }

        private static BigDecimal[] big(double[] v) {
            return new BigDecimal[] {big(v[0]), big(v[1]), big(v[2])};
        }

        /** True when the plane through p + (0, extra, 0) with normal n meets o + t d at some t &lt; 1 (from the ray's side, t &gt; 0 is given). */
        static boolean planeBeforeEnd(Ray ray, double[] p, double[] n, double... extra) {
            BigDecimal[] point = big(p);
            if (extra.length > 0) {
                point[1] = point[1].add(big(extra[0]));
            }
            BigDecimal[] normal = big(n);
            BigDecimal[] o = {big(ray.ox), big(ray.oy), big(ray.oz)};
            BigDecimal[] d = {big(ray.dx), big(ray.dy), big(ray.dz)};
            BigDecimal numerator = dot(normal, new BigDecimal[] {point[0].subtract(o[0]), point[1].subtract(o[1]), point[2].subtract(o[2])});
            BigDecimal denominator = dot(normal, d);
            // t = N / D < 1 with t > 0: N and D of one sign and |N| < |D|
            return denominator.signum() != 0 && numerator.signum() == denominator.signum()
                   && numerator.abs().compareTo(denominator.abs()) < 0;
        }

        /** The plane of the triangle, its normal (b - a) x (c - a) in exact arithmetic. */
        static boolean triangleBeforeEnd(Ray ray, double[][] v) {
            BigDecimal[] a = big(v[0]);
            BigDecimal[] e1 = {big(v[1][0]).subtract(a[0]), big(v[1][1]).subtract(a[1]), big(v[1][2]).subtract(a[2])};
            BigDecimal[] e2 = {big(v[2][0]).subtract(a[0]), big(v[2][1]).subtract(a[1]), big(v[2][2]).subtract(a[2])};
            BigDecimal[] n = {e1[1].multiply(e2[2]).subtract(e1[2].multiply(e2[1])), e1[2].multiply(e2[0]).subtract(e1[0].multiply(e2[2])),
                              e1[0].multiply(e2[1]).subtract(e1[1].multiply(e2[0]))};
            BigDecimal[] o = {big(ray.ox), big(ray.oy), big(ray.oz)};
            BigDecimal[] d = {big(ray.dx), big(ray.dy), big(ray.dz)};
            BigDecimal numerator = dot(n, new BigDecimal[] {a[0].subtract(o[0]), a[1].subtract(o[1]), a[2].subtract(o[2])});
            BigDecimal denominator = dot(n, d);
            return denominator.signum() != 0 && numerator.signum() == denominator.signum()
                   && numerator.abs().compareTo(denominator.abs()) < 0;
        }

        /**
         * True when the ray's end o + d lies strictly inside the sphere (or, with {@code cylinder},
         * the infinite cylinder about y) of centre c and radius r: from outside, it then crossed
         * the surface before its end.
         */
        static boolean endInside(Ray ray, double[] c, double r, boolean cylinder) {
            BigDecimal x = big(ray.ox).add(big(ray.dx)).subtract(big(c[0]));
            BigDecimal y = cylinder ? BigDecimal.ZERO : big(ray.oy).add(big(ray.dy)).subtract(big(c[1]));
            BigDecimal z = big(ray.oz).add(big(ray.dz)).subtract(big(c[2]));
            BigDecimal g = x.multiply(x).add(y.multiply(y)).add(z.multiply(z)).subtract(big(r).multiply(big(r)));
            return g.signum() < 0;
        }
    }
}

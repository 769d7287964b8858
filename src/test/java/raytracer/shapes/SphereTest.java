package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.MutableVec3;

class SphereTest {
    private final HitTesting h = new HitTesting();
    private final Sphere unit = new Sphere(Point3D.ORIGIN, 1);

    @Test
    void rayFromOutsideHitsTheNearSide() {
        ShadeRec sr = h.hit(unit, ray(0, 0, 5, 0, 0, -1));
        assertNotNull(sr);
        assertEquals(4, sr.t, 1e-15);
        assertEquals(1, sr.hitPoint.z, 1e-15);
        assertEquals(1, sr.normal.z, 1e-15);
        assertTrue(sr.frontFace);
    }

    @Test
    void rayFromInsideHitsTheFarSideWithNormalTurnedInward() {
        ShadeRec sr = h.hit(unit, ray(0, 0, 0, 1, 0, 0));
        assertNotNull(sr);
        assertEquals(1, sr.t, 1e-15);
        assertFalse(sr.frontFace);
        assertEquals(-1, sr.normal.x, 1e-15);
    }

    @Test
    void aTangentRayTouchesWithoutCrossingAndMisses() {
        // the double root at t = 5 used to be a hit whose normal (1, 0, 0) has n . d = 0: a back face
        for (double[] o : new double[][] {{1, 0, 5}, {-1, 0, 5}, {0, 1, 5}, {0, -1, 5}}) {
            Ray tangent = ray(o[0], o[1], o[2], 0, 0, -1);
            assertNull(h.hit(unit, tangent), "tangent at " + o[0] + ", " + o[1]);
            assertFalse(h.shadowHit(unit, tangent, Double.POSITIVE_INFINITY));
        }
        assertNull(h.hit(unit, ray(1 + 1e-9, 0, 5, 0, 0, -1)));
        // a scaled instance sees the same double root in its own space
        Instance twice = new Instance(unit, Matrix4.scale(2, 2, 2));
        assertNull(h.hit(twice, ray(2, 0, 5, 0, 0, -1)));
    }

    @Test
    void aRayJustInsideTheTangentEntersByTheFrontAndLeavesByTheBack() {
        Ray grazing = ray(1 - 1e-9, 0, 5, 0, 0, -1);
        ShadeRec sr = h.hit(unit, grazing);
        assertNotNull(sr);
        assertTrue(sr.frontFace);
        assertTrue(sr.normal.z > 0, "the normal faces the ray");
        assertEquals("FB", h.faces(unit, grazing));
        // from inside, along the same line, the wall ahead is a back face
        ShadeRec inside = h.hit(unit, ray(1 - 1e-9, 0, 0, 0, 0, -1));
        assertNotNull(inside);
        assertFalse(inside.frontFace);
    }

    @Test
    void raysGrazingTheSilhouetteEnterBeforeTheyLeave() {
        h.assertEntersBeforeLeaving("grazing a sphere", new Sphere(new Point3D(0.3, -0.2, 0.1), 1), new double[] {0.3, -0.2, 0.1}, 3);
        h.assertEntersBeforeLeaving("grazing a moved ellipsoid", new Instance(unit, Matrix4.rotateY(30)
            .multiply(Matrix4.scale(2, 1, 0.5))), new double[] {0, 0, 0}, 3);
    }

    @Test
    void sphereBehindTheRayIsMissed() {
        assertNull(h.hit(unit, ray(0, 0, 5, 0, 0, 1)));
        assertFalse(h.shadowHit(unit, ray(0, 0, 5, 0, 0, 1), Double.POSITIVE_INFINITY));
    }

    @Test
    void shadowHitRespectsTMax() {
        assertTrue(h.shadowHit(unit, ray(0, 0, 5, 0, 0, -1), 4.5));
        assertFalse(h.shadowHit(unit, ray(0, 0, 5, 0, 0, -1), 3.5));
    }

    @Test
    void smallFarSphereKeepsItsPrecision() {
        Sphere tiny = new Sphere(new Point3D(1e6, 0, 0), 1e-3);
        ShadeRec sr = h.hit(tiny, ray(0, 0, 0, 1, 0, 0));
        assertNotNull(sr);
        assertEquals(1e6 - 1e-3, sr.t, 1e-9);
        // a ray passing at 0.9 r from the centre still hits, at 1.1 r it misses
        assertNotNull(h.hit(tiny, ray(0, 0.9e-3, 0, 1, 0, 0)));
        assertNull(h.hit(tiny, ray(0, 1.1e-3, 0, 1, 0, 0)));
    }

    @Test
    void hitPointsLieOnTheSphereWithinTheirErrorBoundAtEveryScale() {
        SplittableRandom random = new SplittableRandom(7);
        for (int i = 0; i < 20_000; i++) {
            double scale = Math.pow(10, -4 + 10 * random.nextDouble());
            Point3D c = new Point3D(scale * (random.nextDouble() - 0.5) * 8, scale * (random.nextDouble() - 0.5) * 8,
                                    scale * (random.nextDouble() - 0.5) * 8);
            double r = scale * (0.1 + random.nextDouble());
            Sphere s = new Sphere(c, r);
            double dx = random.nextDouble() - 0.5;
            double dy = random.nextDouble() - 0.5;
            double dz = random.nextDouble() - 0.5;
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            // aim at the centre from 3..13 radii away, so that the ray always hits
            double dist = r * (3 + 10 * random.nextDouble());
            ShadeRec sr = h.hit(s, ray(c.x() - dist * dx / len, c.y() - dist * dy / len, c.z() - dist * dz / len,
                                       dx / len, dy / len, dz / len));
            assertNotNull(sr, "ray at the centre missed at scale " + scale);
            double ex = sr.hitPoint.x - c.x();
            double ey = sr.hitPoint.y - c.y();
            double ez = sr.hitPoint.z - c.z();
            double off = Math.abs(Math.sqrt(ex * ex + ey * ey + ez * ez) - r);
            double bound = sr.hitError.x + sr.hitError.y + sr.hitError.z;
            assertTrue(off <= bound, "hit point " + off + " off the surface, bound " + bound);
        }
    }

    /** The near root of |o + t d - c|^2 = r^2 in exact arithmetic (40 digits), by the textbook formula. */
    private static double exactNearRoot(Ray ray, Point3D c, double r) {
        MathContext mc = new MathContext(40);
        BigDecimal[] f = {exact(ray.ox).subtract(exact(c.x())), exact(ray.oy).subtract(exact(c.y())), exact(ray.oz).subtract(exact(c.z()))};
        BigDecimal[] d = {exact(ray.dx), exact(ray.dy), exact(ray.dz)};
        BigDecimal a = BigDecimal.ZERO;
        BigDecimal halfB = BigDecimal.ZERO;
        BigDecimal cc = exact(r).multiply(exact(r)).negate();
        for (int i = 0; i < 3; i++) {
            a = a.add(d[i].multiply(d[i]));
            halfB = halfB.add(f[i].multiply(d[i]));
            cc = cc.add(f[i].multiply(f[i]));
        }
        BigDecimal root = halfB.multiply(halfB).subtract(a.multiply(cc)).sqrt(mc);
        return halfB.negate().subtract(root).divide(a, mc).doubleValue();
    }

    private static BigDecimal exact(double v) {
        return new BigDecimal(v);
    }

    /** How far p lies from the sphere's surface, exactly: (|p - c|^2 - r^2) / (|p - c| + r). */
    private static double exactDistanceToSurface(MutableVec3 p, Point3D c, double r) {
        MathContext mc = new MathContext(40);
        BigDecimal[] e = {exact(p.x).subtract(exact(c.x())), exact(p.y).subtract(exact(c.y())), exact(p.z).subtract(exact(c.z()))};
        BigDecimal square = e[0].multiply(e[0]).add(e[1].multiply(e[1])).add(e[2].multiply(e[2]));
        return square.subtract(exact(r).multiply(exact(r))).divide(square.sqrt(mc).add(exact(r)), mc).doubleValue();
    }

    @Test
    void aHugeSphereSeenFromCloseByIsHitOnItsNearSideAndItsHitPointsAreExact() {
        // the ray's origin relative to the centre, h + r, is not a double once r is past 2^53 h:
        // the near root was lost (radius 1e16 and more), or far off (1e14: 3e-3 out of 6)
        SplittableRandom random = new SplittableRandom(3);
        for (double r : new double[] {1e6, 1e10, 1e14, 1e16, 1e20, 1e25}) {
            Point3D c = new Point3D(0, -r, 0);
            Sphere s = new Sphere(c, r);
            for (int i = 0; i < 100; i++) {
                double height = Math.pow(10, -3 + 6 * random.nextDouble());
                double dx = random.nextDouble() - 0.5;
                double dz = random.nextDouble() - 0.5;
                double dy = -0.1 - random.nextDouble();
                Ray ray = ray(random.nextDouble() - 0.5, height, random.nextDouble() - 0.5, dx, dy, dz);
                String what = "radius " + r + ", " + ray;
                double expected = exactNearRoot(ray, c, r);
                ShadeRec sr = h.hit(s, ray);
                assertNotNull(sr, what);
                assertEquals(expected, sr.t, 1e-9 * expected, what);
                assertTrue(sr.frontFace, what);
                MutableVec3 n = sr.geometricNormal;
                double offset = Math.abs(n.x) * sr.hitError.x + Math.abs(n.y) * sr.hitError.y + Math.abs(n.z) * sr.hitError.z;
                double off = Math.abs(exactDistanceToSurface(sr.hitPoint, c, r));
                assertTrue(off <= offset, what + ": hit point " + off + " off the surface, bound " + offset);
                // small enough for the shadow of a ball 1 unit tall to start where it should
                assertTrue(offset < 1e-4 * Math.max(1, sr.t), what + ": bound " + offset);
                // a ray leaving towards the sky does not find the sphere again; one going in leaves it far away
                Ray out = sr.spawnRay(0.3, 1, 0.2, new Ray());
                assertFalse(s.shadowHit(out, Double.POSITIVE_INFINITY, sr), what + ": self-shadowed");
                Ray in = sr.spawnRay(0.3, -1, 0.2, new Ray());
                assertTrue(exactNearRoot(in, c, r) < 0, what + ": the inward ray starts inside");
            }
        }
    }

    @Test
    void badRadiusIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, -1));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, 0));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, Double.NaN));
        // radius 1e160 rendered black without a word: its square is infinite
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, 1e151));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(new Point3D(0, -1e150, 0), 1e149));
        assertNotNull(h.hit(new Sphere(new Point3D(0, -5e149, 0), 5e149), ray(0, 1, 6, 0, -1, -6)));
    }

    @Test
    void uvsAreLongitudeAndLatitudeAroundTheYAxis() {
        Sphere sphere = new Sphere(new Point3D(3, -2, 1), 2);
        // (direction from the centre, u, v): u = (atan2(x, z) + pi) / 2pi, v = 1 - theta / pi (Suffern 29.3)
        double[][] cases = {
            {0, 0, 1, 0.5, 0.5}, {1, 0, 0, 0.75, 0.5}, {0, 0, -1, 1.0, 0.5}, {-1, 0, 0, 0.25, 0.5},
            {0, 1, 0, 0.5, 1}, {0, -1, 0, 0.5, 0}, {0, Math.sqrt(0.5), Math.sqrt(0.5), 0.5, 0.75},
        };
        for (double[] c : cases) {
            // a ray from outside straight at the centre along -direction
            ShadeRec sr = h.hit(sphere, ray(3 + 5 * c[0], -2 + 5 * c[1], 1 + 5 * c[2], -c[0], -c[1], -c[2]));
            assertNotNull(sr);
            String what = "direction " + c[0] + ", " + c[1] + ", " + c[2];
            if (Math.abs(c[1]) < 1) {
                // at the poles u is undefined; anything in [0, 1] will do
                double wrapped = Math.IEEEremainder(sr.u - c[3], 1); // u = 0 and u = 1 are the same seam
                assertEquals(0, wrapped, 1e-12, "u " + sr.u + ", " + what);
            }
            assertTrue(sr.u >= 0 && sr.u <= 1, what);
            assertEquals(c[4], sr.v, 1e-12, "v, " + what);
        }
    }
}

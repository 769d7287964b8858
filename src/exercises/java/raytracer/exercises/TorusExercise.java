package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.exercises.Scratch.ray;

import java.lang.reflect.Constructor;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Ray;

/**
 * Exercise 5: a torus (Suffern, chapter 19), centred at the origin around the y axis, of swept
 * radius a (centre of the tube to the axis) and tube radius b. Checked against closed forms and
 * against an independent search: sphere tracing of the torus's exact distance function.
 */
@Tag("exercise")
class TorusExercise {
    private static final double A = 2;
    private static final double B = 0.5;
    private static Constructor<? extends GeometricObject> torus;

    private final Scratch scratch = new Scratch();

    @BeforeAll
    static void findTheClass() {
        torus = Student.constructor(5, "raytracer.shapes.Torus", GeometricObject.class, double.class, double.class);
    }

    private static GeometricObject torus(double a, double b) {
        return Student.create(torus, a, b);
    }

    /** Distance from p to the torus's surface, negative inside the tube. */
    private static double distance(double a, double b, double x, double y, double z) {
        return Math.hypot(Math.hypot(x, z) - a, y) - b;
    }

    @Test
    void aRayAlongTheAxisPassesThroughTheHole() {
        GeometricObject t = torus(A, B);
        ShadeRec sr = scratch.hit(t, ray(0, 5, 0, 0, -1, 0));
        assertNull(sr, "Torus(2, 0.5), ray from (0, 5, 0) down the axis: it passes through the hole, but hit() recorded t = "
                       + (sr == null ? 0 : sr.t));
        assertFalse(t.shadowHit(ray(0, 5, 0, 0, -1, 0), Double.POSITIVE_INFINITY, scratch.sr),
                    "Torus(2, 0.5), shadow ray from (0, 5, 0) down the axis: it passes through the hole");
    }

    @Test
    void aRayDownThroughTheTubesCentreCircleHitsItsTop() {
        ShadeRec sr = scratch.hit(torus(A, B), ray(A, 5, 0, 0, -1, 0));
        String ray = "Torus(2, 0.5), ray from (2, 5, 0) straight down: ";
        assertNotNull(sr, ray + "a ray down at x = a must hit the top of the tube");
        assertEquals(5 - B, sr.t, 1e-9, ray + "the top of the tube lies at y = b, t = 5 - b");
        assertEquals(B, sr.hitPoint.y, 1e-9, ray + "completeHit must write the hit point, y = b");
        assertEquals(1, sr.normal.y, 1e-9, ray + "the normal at the top of the tube points up, got " + sr.normal);
        assertTrue(sr.frontFace, ray + "it meets the outside of the surface: frontFace must be true");
    }

    @Test
    void distancesAreInUnitsOfTheRaysParameterNotOfLength() {
        // instances hand the torus unnormalised directions: t must still put o + t d on the surface
        ShadeRec sr = scratch.hit(torus(A, B), ray(A, 5, 0, 0, -4, 0));
        String ray = "Torus(2, 0.5), ray from (2, 5, 0) with direction (0, -4, 0), four times unit length: ";
        assertNotNull(sr, ray + "it must hit the top of the tube");
        assertEquals((5 - B) / 4, sr.t, 1e-9, ray + "t is in units of the direction, (5 - b) / 4: do not normalise it away");
    }

    @Test
    void aRayAlongTheEquatorMeetsTheOuterAndTheInnerSurface() {
        GeometricObject t = torus(A, B);
        ShadeRec outer = scratch.hit(t, ray(-10, 0, 0, 1, 0, 0));
        String fromOutside = "Torus(2, 0.5), ray from (-10, 0, 0) along +x: ";
        assertNotNull(outer, fromOutside + "it must hit the outer equator");
        assertEquals(10 - (A + B), outer.t, 1e-9, fromOutside + "the outer equator lies at x = -(a + b), t = 10 - (a + b)");
        assertEquals(-1, outer.normal.x, 1e-9, fromOutside + "the outer equator's normal points along -x, got " + outer.normal);
        // from the centre of the hole, the first surface is the inner equator at distance a - b
        ShadeRec inner = scratch.hit(t, ray(0, 0, 0, 1, 0, 0));
        String fromCentre = "Torus(2, 0.5), ray from the centre (0, 0, 0) along +x: ";
        assertNotNull(inner, fromCentre + "it must hit the inner equator");
        assertEquals(A - B, inner.t, 1e-9, fromCentre + "the inner equator lies at x = a - b");
        assertEquals(-1, inner.normal.x, 1e-9, fromCentre + "the inner equator's normal points towards the axis, got " + inner.normal);
        assertTrue(inner.frontFace, fromCentre + "it meets the outside of the surface: frontFace must be true");
    }

    @Test
    void aRayFromInsideTheTubeLeavesThroughItsBackFace() {
        ShadeRec sr = scratch.hit(torus(A, B), ray(0, 0, A, 0, 1, 0));
        String ray = "Torus(2, 0.5), ray from (0, 0, 2), inside the tube, straight up: ";
        assertNotNull(sr, ray + "it must hit the tube's top from inside");
        assertEquals(B, sr.t, 1e-9, ray + "the tube's top is b above the centre circle");
        assertFalse(sr.frontFace, ray + "the ray leaves the tube: it sees the back of the surface, frontFace false");
        assertEquals(-1, sr.normal.y, 1e-9, ray + "the normal is turned to face the ray, (0, -1, 0), got " + sr.normal);
    }

    @Test
    void raysJustAboveTheTopMissAndJustBelowItHit() {
        GeometricObject t = torus(A, B);
        ShadeRec above = scratch.hit(t, ray(-10, B + 1e-6, 0, 1, 0, 0));
        assertNull(above, "Torus(2, 0.5), ray along +x at y = b + 1e-6, just above the top: it misses, but hit() recorded t = "
                          + (above == null ? 0 : above.t));
        ShadeRec sr = scratch.hit(t, ray(-10, B - 1e-3, 0, 1, 0, 0));
        String below = "Torus(2, 0.5), ray from (-10, b - 1e-3, 0) along +x, just below the top: ";
        assertNotNull(sr, below + "it must hit the tube");
        double x = -A - Math.sqrt(B * B - (B - 1e-3) * (B - 1e-3));
        assertEquals(x + 10, sr.t, 1e-9, below + "it meets the tube where the circle of radius b says, x = " + x);
    }

    @Test
    void shadowHitRespectsTMax() {
        GeometricObject t = torus(A, B);
        Ray r = ray(-10, 0, 0, 1, 0, 0);
        String ray = "Torus(2, 0.5), shadow ray from (-10, 0, 0) along +x, which meets it at t = 10 - (a + b) = 7.5: ";
        assertTrue(t.shadowHit(r, 10 - (A + B) + 1e-6, scratch.sr), ray + "shadowHit(ray, 7.5 + 1e-6) must be true");
        assertFalse(t.shadowHit(r, 10 - (A + B) - 1e-6, scratch.sr), ray + "shadowHit(ray, 7.5 - 1e-6) must be false: tMax ends it");
        assertFalse(t.shadowHit(ray(-10, 0, 0, -1, 0, 0), Double.POSITIVE_INFINITY, scratch.sr),
                    "Torus(2, 0.5), shadow ray from (-10, 0, 0) along -x: the torus is behind it");
    }

    @Test
    void theBoundingBoxHoldsTheTorusAndLittleElse() {
        BBox box = torus(A, B).boundingBox();
        double r = A + B;
        for (double[] p : new double[][] {{r, 0, 0}, {-r, 0, 0}, {0, 0, r}, {0, 0, -r}, {A, B, 0}, {-A, -B, 0}}) {
            assertTrue(box.contains(p[0], p[1], p[2]), "the box must hold the extreme point " + p[0] + ", " + p[1] + ", " + p[2]);
        }
        assertTrue(box.y1() - box.y0() <= 2 * B * 1.01 && box.x1() - box.x0() <= 2 * r * 1.01,
                   "a box of the torus is (a + b, b, a + b) either side of the centre, got " + box);
    }

    @Test
    void badRadiiAreRefused() {
        String rule = ": a > b > 0, else IllegalArgumentException";
        assertThrows(IllegalArgumentException.class, () -> torus(1, 0), "Torus(1, 0)" + rule);
        assertThrows(IllegalArgumentException.class, () -> torus(1, -0.5), "Torus(1, -0.5)" + rule);
        assertThrows(IllegalArgumentException.class, () -> torus(0.5, 1), "Torus(0.5, 1): a ring torus needs a > b" + rule);
        assertThrows(IllegalArgumentException.class, () -> torus(Double.NaN, 0.5), "Torus(NaN, 0.5)" + rule);
    }

    /**
     * Random rays, with random origins around the torus and random directions, against sphere
     * tracing of its exact distance function: the same first hit, or both a miss; hit points on the
     * surface within their error bound; normals along the distance function's gradient.
     */
    @Test
    void randomRaysAgreeWithSphereTracing() {
        SplittableRandom random = new SplittableRandom(11);
        int hits = 0;
        for (int i = 0; i < 5000; i++) {
            double a = 0.2 + 3 * random.nextDouble();
            double b = a * (0.05 + 0.9 * random.nextDouble());
            GeometricObject t = torus(a, b);
            double s = 3 * (a + b);
            double ox = s * (2 * random.nextDouble() - 1);
            double oy = s * (2 * random.nextDouble() - 1);
            double oz = s * (2 * random.nextDouble() - 1);
            if (distance(a, b, ox, oy, oz) < 1e-3 * b) {
                continue; // on or inside the tube: sphere tracing needs an origin outside
            }
            // aim near the torus so that about half the rays hit
            double tx = (a + b) * (2 * random.nextDouble() - 1) - ox;
            double ty = b * (2 * random.nextDouble() - 1) - oy;
            double tz = (a + b) * (2 * random.nextDouble() - 1) - oz;
            double len = Math.sqrt(tx * tx + ty * ty + tz * tz);
            Ray r = ray(ox, oy, oz, tx / len, ty / len, tz / len);
            double expected = sphereTrace(a, b, r);
            if (Double.isNaN(expected)) {
                continue; // grazing: the search did not settle
            }
            ShadeRec sr = scratch.hit(t, r);
            String where = "random ray " + i + ", Torus(" + a + ", " + b + "), from (" + ox + ", " + oy + ", " + oz + ") along ("
                           + r.dx + ", " + r.dy + ", " + r.dz + ")";
            if (expected == Double.POSITIVE_INFINITY) {
                assertNull(sr, where + " misses the torus but a hit was reported at t = " + (sr == null ? 0 : sr.t));
                continue;
            }
            assertNotNull(sr, where + " hits the torus at t = " + expected);
            hits++;
            assertEquals(expected, sr.t, 1e-7 * s, where + ": the nearest root must be t = " + expected + " (sphere tracing), to 1e-7 of the scene");
            assertEquals(0, distance(a, b, sr.hitPoint.x, sr.hitPoint.y, sr.hitPoint.z),
                         1e-9 * s + sr.hitError.x + sr.hitError.y + sr.hitError.z, where + ": the hit point lies off the surface");
            assertTrue(sr.hitError.x >= 0 && sr.hitError.y >= 0 && sr.hitError.z >= 0 && sr.hitError.x < 1e-6 * s,
                       where + ": hitError must bound the hit point's rounding error, got " + sr.hitError);
            double[] n = gradient(a, sr.hitPoint.x, sr.hitPoint.y, sr.hitPoint.z);
            double along = Math.abs(n[0] * sr.normal.x + n[1] * sr.normal.y + n[2] * sr.normal.z);
            assertEquals(1, along, 1e-7, where + ": the normal must be the surface's, along the distance function's gradient ("
                                         + n[0] + ", " + n[1] + ", " + n[2] + "), got " + sr.normal);
            assertTrue(r.dx * sr.normal.x + r.dy * sr.normal.y + r.dz * sr.normal.z < 0, where + ": the normal faces the ray");
            assertTrue(t.shadowHit(r, sr.t * (1 + 1e-6), scratch.sr) && !t.shadowHit(r, sr.t * (1 - 1e-6), scratch.sr),
                       where + ": shadowHit must find the same hit, t = " + sr.t + " (true just beyond it, false just before)");
        }
        assertTrue(hits > 1000, "too few hits to judge: " + hits + " of 5000 rays (more than 1000 expected)");
    }

    /**
     * A ray spawned from a hit along the normal, on the side the ray came from
     * ({@code ShadeRec.spawnRay}, which starts it beyond the hit point's error bound), must not
     * find the torus where it left it: along that line the torus lies at least 2b (across the tube)
     * or 2 (a - b) (across the hole) away. A hit that leaves {@code hitError} at 0 starts the ray
     * within the hit point's rounding, on either side of the surface, and half such rays hit the
     * torus again at once (the shadow acne of the book's kEpsilon, chapter 16). Tori of every size
     * from 1e-4 to 1e6, hit from outside, from up to 150 times their size away, and from inside the
     * tube.
     */
    @Test
    void raysSpawnedFromAHitLeaveTheSurface() {
        SplittableRandom random = new SplittableRandom(23);
        Ray spawned = new Ray();
        int checked = 0;
        for (int i = 0; i < 4000; i++) {
            double size = Math.pow(10, -4 + 10 * random.nextDouble());
            double a = size * (0.5 + random.nextDouble());
            double b = a * (0.05 + 0.9 * random.nextDouble());
            GeometricObject t = torus(a, b);
            double[] o;
            if (i % 4 == 0) {
                // inside the tube: a point of the tube's centre circle, moved less than b off it
                double phi = 2 * Math.PI * random.nextDouble();
                double rho = a + 0.5 * b * (2 * random.nextDouble() - 1);
                o = new double[] {rho * Math.cos(phi), 0.5 * b * (2 * random.nextDouble() - 1), rho * Math.sin(phi)};
            } else {
                double reach = 1.5 * (a + b) * Math.pow(10, 2 * random.nextDouble());
                double[] u = unitVector(random);
                o = new double[] {reach * u[0], reach * u[1], reach * u[2]};
            }
            double tx = (a + b) * (2 * random.nextDouble() - 1) - o[0];
            double ty = b * (2 * random.nextDouble() - 1) - o[1];
            double tz = (a + b) * (2 * random.nextDouble() - 1) - o[2];
            double len = Math.sqrt(tx * tx + ty * ty + tz * tz);
            ShadeRec sr = scratch.hit(t, ray(o[0], o[1], o[2], tx / len, ty / len, tz / len));
            if (sr == null) {
                continue;
            }
            checked++;
            String from = "Torus(" + a + ", " + b + "), hit " + i + " at (" + sr.hitPoint.x + ", " + sr.hitPoint.y + ", " + sr.hitPoint.z
                          + ") with hitError " + sr.hitError;
            sr.spawnRay(sr.geometricNormal.x, sr.geometricNormal.y, sr.geometricNormal.z, spawned);
            ShadeRec again = scratch.hit(t, spawned);
            assertTrue(again == null || again.t >= Math.min(b, a - b), from + ": a ray spawned from the hit along its normal (facing the ray) "
                       + "hits the torus again at t = " + (again == null ? 0 : again.t) + ", where no surface lies: hitError must "
                       + "bound the hit point's rounding, so that the ray starts beyond it");
        }
        assertTrue(checked > 2000, "too few hits to judge: " + checked + " of 4000 rays (more than 2000 expected)");
    }

    private static double[] unitVector(SplittableRandom random) {
        double z = 2 * random.nextDouble() - 1;
        double phi = 2 * Math.PI * random.nextDouble();
        double r = Math.sqrt(1 - z * z);
        return new double[] {r * Math.cos(phi), r * Math.sin(phi), z};
    }

    /**
     * The first hit by sphere tracing (Hart 1996): step by the distance to the surface, which never
     * oversteps it. +infinity when the ray leaves for good, NaN when 100,000 steps did not settle.
     */
    private static double sphereTrace(double a, double b, Ray r) {
        double reach = Math.sqrt(r.ox * r.ox + r.oy * r.oy + r.oz * r.oz) + a + b;
        double t = 0;
        for (int step = 0; step < 100_000; step++) {
            double d = distance(a, b, r.ox + t * r.dx, r.oy + t * r.dy, r.oz + t * r.dz);
            if (d < 1e-12 * (a + b)) {
                return t;
            }
            t += d;
            if (t > 2 * reach) {
                return Double.POSITIVE_INFINITY;
            }
        }
        return Double.NaN;
    }

    /** The unit gradient of the distance function at a point of the surface. */
    private static double[] gradient(double a, double x, double y, double z) {
        double rho = Math.hypot(x, z);
        double gx = (rho - a) * x / rho;
        double gy = y;
        double gz = (rho - a) * z / rho;
        double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
        return new double[] {gx / len, gy / len, gz / len};
    }
}

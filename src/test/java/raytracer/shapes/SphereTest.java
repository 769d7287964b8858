package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Point3D;

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
    void tangentRayTouchesAndARayJustOutsideMisses() {
        ShadeRec sr = h.hit(unit, ray(1, 0, 5, 0, 0, -1));
        assertNotNull(sr);
        assertEquals(5, sr.t, 1e-7);
        assertNull(h.hit(unit, ray(1 + 1e-9, 0, 5, 0, 0, -1)));
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

    @Test
    void badRadiusIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, -1));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, 0));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Point3D.ORIGIN, Double.NaN));
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

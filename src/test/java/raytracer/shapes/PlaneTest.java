package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Normal;
import raytracer.math.Point3D;

class PlaneTest {
    private final HitTesting h = new HitTesting();
    private final Plane ground = new Plane(new Point3D(0, 1, 0), new Normal(0, 2, 0));

    @Test
    void obliqueRayHitsAtTheClosedFormDistance() {
        // from (0, 4, 0) along (1, -1, 0)/sqrt2: drops 3 units, so t = 3 sqrt2
        double s = Math.sqrt(0.5);
        ShadeRec sr = h.hit(ground, ray(0, 4, 0, s, -s, 0));
        assertNotNull(sr);
        assertEquals(3 * Math.sqrt(2), sr.t, 1e-14);
        assertEquals(3, sr.hitPoint.x, 1e-14);
        assertEquals(1, sr.hitPoint.y, 0);
        assertEquals(1, sr.normal.y, 0);
    }

    @Test
    void parallelRayMissesWithoutNaN() {
        assertNull(h.hit(ground, ray(0, 4, 0, 1, 0, 0)));
        // a ray lying in the plane: 0 / 0 must not count as a hit
        assertNull(h.hit(ground, ray(0, 1, 0, 1, 0, 0)));
        assertFalse(h.shadowHit(ground, ray(0, 1, 0, 1, 0, 0), Double.POSITIVE_INFINITY));
    }

    @Test
    void hitFromBelowTurnsTheNormalDown() {
        ShadeRec sr = h.hit(ground, ray(0, -3, 0, 0, 1, 0));
        assertNotNull(sr);
        assertFalse(sr.frontFace);
        assertEquals(-1, sr.normal.y, 0);
        assertTrue(h.shadowHit(ground, ray(0, -3, 0, 0, 1, 0), 5));
    }
}

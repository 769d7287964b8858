package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Ray;

class CylinderTest {
    private final HitTesting h = new HitTesting();
    private final Cylinder open = new Cylinder(0, 2, 1, false);
    private final Cylinder closed = new Cylinder(0, 2, 1, true);

    @Test
    void sideHitHasARadialNormal() {
        double s = Math.sqrt(0.5);
        ShadeRec sr = h.hit(open, ray(5 * s, 1, 5 * s, -s, 0, -s));
        assertNotNull(sr);
        assertEquals(4, sr.t, 1e-14);
        assertEquals(s, sr.normal.x, 1e-14);
        assertEquals(0, sr.normal.y, 0);
        assertEquals(s, sr.normal.z, 1e-14);
    }

    @Test
    void sideOutsideTheHeightRangeIsMissed() {
        assertNull(h.hit(open, ray(5, 2.5, 0, -1, 0, 0)));
        assertNull(h.hit(open, ray(5, -0.5, 0, -1, 0, 0)));
    }

    @Test
    void capsCloseTheCylinder() {
        ShadeRec top = h.hit(closed, ray(0.3, 5, 0.2, 0, -1, 0));
        assertNotNull(top);
        assertEquals(3, top.t, 0);
        assertEquals(2, top.hitPoint.y, 0);
        assertEquals(1, top.normal.y, 0);
        ShadeRec bottom = h.hit(closed, ray(0.3, -5, 0.2, 0, 1, 0));
        assertNotNull(bottom);
        assertEquals(5, bottom.t, 0);
        assertEquals(-1, bottom.normal.y, 0);
    }

    @Test
    void rayAlongTheAxisPassesThroughAnOpenCylinder() {
        assertNull(h.hit(open, ray(0, 5, 0, 0, -1, 0)));
        assertFalse(h.shadowHit(open, ray(0, 5, 0, 0, -1, 0), Double.POSITIVE_INFINITY));
    }

    @Test
    void rayAlongTheAxisFromInsideHitsTheTopCapFromBelow() {
        ShadeRec sr = h.hit(closed, ray(0, 0.5, 0, 0, 1, 0));
        assertNotNull(sr);
        assertEquals(1.5, sr.t, 0);
        assertFalse(sr.frontFace);
        assertEquals(-1, sr.normal.y, 0);
    }

    @Test
    void openCylinderSeenFromInsideShowsItsInnerWall() {
        ShadeRec sr = h.hit(open, ray(0, 1, 0, 1, 0, 0));
        assertNotNull(sr);
        assertEquals(1, sr.t, 1e-15);
        assertEquals(-1, sr.normal.x, 1e-15);
    }

    @Test
    void rayPastTheRimOfTheCapMisses() {
        assertNull(h.hit(closed, ray(1.01, 5, 0, 0, -1, 0)));
    }

    @Test
    void raysThatOnlyTouchTheSurfaceMiss() {
        // tangent to the side (the double root used to be a back face), in a cap's plane, along the side
        for (Cylinder c : new Cylinder[] {open, closed}) {
            assertNull(h.hit(c, ray(1, 1, 5, 0, 0, -1)), "tangent to the side");
            assertFalse(h.shadowHit(c, ray(1, 1, 5, 0, 0, -1), Double.POSITIVE_INFINITY));
        }
        assertNull(h.hit(closed, ray(-5, 2, 0, 1, 0, 0)), "in the top cap's plane");
        assertNull(h.hit(closed, ray(1, 5, 0, 0, -1, 0)), "along the side");
    }

    @Test
    void aRayGrazingTheSideEntersByTheFrontAndLeavesByTheBack() {
        for (Cylinder c : new Cylinder[] {open, closed}) {
            Ray grazing = ray(1 - 1e-9, 1, 5, 0, 0, -1);
            ShadeRec sr = h.hit(c, grazing);
            assertNotNull(sr);
            assertTrue(sr.frontFace);
            assertTrue(sr.normal.z > 0, "the normal faces the ray");
            assertEquals("FB", h.faces(c, grazing));
        }
    }

    @Test
    void raysGrazingTheSilhouetteOfTheClosedCylinderEnterBeforeTheyLeave() {
        // through the rim, testing the side's height and the cap's radius apart let rays slip
        // between them and meet the inside of the wall from outside
        h.assertEntersBeforeLeaving("grazing a closed cylinder", closed, new double[] {0, 1, 0}, 4);
    }
}

package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Point3D;

class BoxTest {
    private final HitTesting h = new HitTesting();
    private final Box box = new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1));

    @Test
    void faceHitHasTheFaceNormalAndAnExactPoint() {
        ShadeRec sr = h.hit(box, ray(0.25, 0.5, 5, 0, 0, -1));
        assertNotNull(sr);
        assertEquals(4, sr.t, 0);
        assertEquals(1, sr.hitPoint.z, 0);
        assertEquals(1, sr.normal.z, 0);
        assertEquals(0, sr.hitError.z, 0, "the face coordinate is snapped, so it carries no error");
    }

    @Test
    void eachOfTheSixFacesGivesItsOwnNormal() {
        double[][] dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (double[] d : dirs) {
            ShadeRec sr = h.hit(box, ray(-5 * d[0] + 0.1, -5 * d[1] + 0.2, -5 * d[2] + 0.3, d[0], d[1], d[2]));
            assertNotNull(sr);
            assertEquals(-d[0], sr.normal.x, 0);
            assertEquals(-d[1], sr.normal.y, 0);
            assertEquals(-d[2], sr.normal.z, 0);
        }
    }

    @Test
    void rayThroughACornerHitsTheCorner() {
        double s = 1 / Math.sqrt(3);
        ShadeRec sr = h.hit(box, ray(3, 3, 3, -s, -s, -s));
        assertNotNull(sr);
        assertEquals(2 * Math.sqrt(3), sr.t, 1e-14);
        assertEquals(1, sr.hitPoint.x, 1e-14);
        assertEquals(1, sr.hitPoint.y, 1e-14);
        assertEquals(1, sr.hitPoint.z, 1e-14);
        assertEquals(1, Math.abs(sr.normal.x) + Math.abs(sr.normal.y) + Math.abs(sr.normal.z), 0);
    }

    @Test
    void rayThroughAnEdgeHitsTheEdge() {
        double s = Math.sqrt(0.5);
        ShadeRec sr = h.hit(box, ray(3, 3, 0.5, -s, -s, 0));
        assertNotNull(sr);
        assertEquals(2 * Math.sqrt(2), sr.t, 1e-14);
        assertEquals(1, sr.hitPoint.x, 1e-14);
        assertEquals(1, sr.hitPoint.y, 1e-14);
    }

    @Test
    void rayJustPastAnEdgeMisses() {
        assertNull(h.hit(box, ray(1 + 1e-12, 5, 0, 0, -1, 0)));
        assertNotNull(h.hit(box, ray(1 - 1e-12, 5, 0, 0, -1, 0)));
    }

    @Test
    void fromInsideTheExitFaceIsHitAndNormalTurnsInward() {
        ShadeRec sr = h.hit(box, ray(0, 0, 0, 0, 1, 0));
        assertNotNull(sr);
        assertEquals(1, sr.t, 0);
        assertFalse(sr.frontFace);
        assertEquals(-1, sr.normal.y, 0);
    }

    @Test
    void aRayInTheFacePlaneMissesAndOneJustInsideHits() {
        // a ray along the plane y = 1 of the top face touches only the boundary: in the slab test
        // (1 - 1) * infinity is NaN, which the comparisons must turn into a miss, not a NaN distance
        for (double y : new double[] {1, -1}) {
            assertNull(h.hit(box, ray(-5, y, 0, 1, 0, 0)), "in the plane y = " + y);
            assertFalse(h.shadowHit(box, ray(-5, y, 0, 1, 0, 0), Double.POSITIVE_INFINITY), "in the plane y = " + y);
            assertNull(h.hit(box, ray(-5, y + Math.copySign(1e-12, y), 0, 1, 0, 0)), "just outside y = " + y);
            ShadeRec sr = h.hit(box, ray(-5, y - Math.copySign(1e-12, y), 0, 1, 0, 0));
            assertNotNull(sr, "just inside y = " + y);
            assertEquals(4, sr.t, 0);
            assertEquals(-1, sr.normal.x, 0);
        }
        // the shadow test of the ray just inside sees the box only within its reach
        assertTrue(h.shadowHit(box, ray(-5, 1 - 1e-12, 0, 1, 0, 0), 4.5));
        assertFalse(h.shadowHit(box, ray(-5, 1 - 1e-12, 0, 1, 0, 0), 3.5));
    }

    @Test
    void flatBoxIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> new Box(new Point3D(0, 0, 0), new Point3D(1, 0, 1)));
    }

    @Test
    void aRayGrazingAFaceEntersByItAndLeavesByTheFaceAhead() {
        // slope 1e-12 down onto the top face, which it meets at x = -0.5; it leaves by x = 1
        ShadeRec sr = h.hit(box, ray(-5, 1 + 4.5e-12, 0, 1, -1e-12, 0));
        assertNotNull(sr);
        assertTrue(sr.frontFace);
        assertEquals(1, sr.normal.y, 0);
        assertEquals("FB", h.faces(box, ray(-5, 1 + 4.5e-12, 0, 1, -1e-12, 0)));
        // a ray touching only an edge, or lying in a face's plane, does not cross the surface
        assertNull(h.hit(box, ray(0, 2, 0, 1, -1, 0)), "touching the edge x = 1, y = 1");
        assertNull(h.hit(box, ray(1, 5, 0.5, 0, -1, 0)), "in the plane x = 1");
    }

    @Test
    void raysGrazingTheSilhouetteEnterBeforeTheyLeave() {
        // near an edge the face nearest the hit point may be the one the ray runs along, of either
        // sign of n . d: the face must be the slab's the ray entered or left by
        h.assertEntersBeforeLeaving("grazing a box", box, new double[] {0, 0, 0}, 4);
        h.assertEntersBeforeLeaving("grazing a flat box", new Box(new Point3D(-3, 0.5, -1), new Point3D(2, 0.5 + 1e-3, 1)),
                                    new double[] {0, 0.5005, 0}, 8);
    }
}

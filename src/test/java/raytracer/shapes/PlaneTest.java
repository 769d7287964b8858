package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Matrix4;
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

    @Test
    void uvsAreDistancesAlongTwoOrthogonalAxesOfThePlane() {
        Point3D anchor = new Point3D(1, -2, 0.5);
        Plane tilted = new Plane(anchor, new Normal(0.3, 1, -0.6));
        SplittableRandom r = new SplittableRandom(4);
        double[] previous = null;
        for (int i = 0; i < 200; i++) {
            // a ray towards the plane from above and to the side
            ShadeRec sr = h.hit(tilted, ray(r.nextDouble(-5, 5), 10, r.nextDouble(-5, 5),
                                            r.nextDouble(-0.5, 0.5), -1, r.nextDouble(-0.5, 0.5)));
            assertNotNull(sr);
            double[] now = {sr.hitPoint.x, sr.hitPoint.y, sr.hitPoint.z, sr.u, sr.v};
            double dx = now[0] - anchor.x();
            double dy = now[1] - anchor.y();
            double dz = now[2] - anchor.z();
            assertEquals(Math.sqrt(dx * dx + dy * dy + dz * dz), Math.hypot(sr.u, sr.v), 1e-9, "distance from the anchor, ray " + i);
            if (previous != null) {
                double ex = now[0] - previous[0];
                double ey = now[1] - previous[1];
                double ez = now[2] - previous[2];
                assertEquals(Math.sqrt(ex * ex + ey * ey + ez * ez), Math.hypot(now[3] - previous[3], now[4] - previous[4]), 1e-9,
                             "(u, v) is an isometry of the plane, ray " + i);
            }
            previous = now;
        }
        // the horizontal ground's axes are z and x
        ShadeRec sr = h.hit(ground, ray(2, 5, 3, 0, -1, 0));
        assertEquals(3, sr.u, 1e-12);
        assertEquals(2, sr.v, 1e-12);
    }

    @Test
    void grazingRaysHitTheFaceTheyComeFrom() {
        h.assertGrazingFaces(ground, new double[] {0.3, 1, -0.2}, new double[] {0, 1, 0}, new double[] {1, 0, 0});
        double s = Math.sqrt(0.5);
        Plane tilted = new Plane(new Point3D(1, 2, 3), new Normal(1, 1, 0));
        h.assertGrazingFaces(tilted, new double[] {1, 2, 3}, new double[] {s, s, 0}, new double[] {0, 0, 1});
    }

    /** Its box is a slab where the normal is an axis (lights read it to know what lies near them), else all of space. */
    @Test
    void aPlaneNormalToAnAxisIsBoundedAlongIt() {
        double inf = Double.POSITIVE_INFINITY;
        assertEquals(new BBox(-inf, -2.5, -inf, inf, -2.5, inf), new Plane(new Point3D(7, -2.5, 3), new Normal(0, -3, 0)).boundingBox());
        assertEquals(new BBox(1, -inf, -inf, 1, inf, inf), new Plane(new Point3D(1, 5, 5), new Normal(2, 0, 0)).boundingBox());
        assertEquals(new BBox(-inf, -inf, 4, inf, inf, 4), new Plane(new Point3D(0, 0, 4), new Normal(0, 0, 1)).boundingBox());
        BBox all = new BBox(-inf, -inf, -inf, inf, inf, inf);
        assertEquals(all, new Plane(new Point3D(0, 0, 0), new Normal(0, 1, 1e-300)).boundingBox());
        // turned by an instance, the slab would lie elsewhere: it bounds nothing narrower than space
        assertEquals(all, new Instance(new Plane(new Point3D(0, 1, 0), new Normal(0, 1, 0)), Matrix4.rotateX(30)).boundingBox());
    }
}

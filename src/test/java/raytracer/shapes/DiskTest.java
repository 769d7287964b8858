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
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/** The disk of a disk light, against closed forms. */
class DiskTest {
    private final HitTesting h = new HitTesting();
    private final Point3D centre = new Point3D(1, 2, -3);
    /** Normal (1, 2, 2) / 3, radius 1.5. */
    private final Disk disk = new Disk(centre, new Vector3D(1, 2, 2), 1.5);
    private final double[] n = {1 / 3.0, 2 / 3.0, 2 / 3.0};
    /** Two unit vectors in the disk's plane: (2, -1, 0) / sqrt5 and n x that. */
    private final double[] a = {2 / Math.sqrt(5), -1 / Math.sqrt(5), 0};
    private final double[] b = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]};

    /** The point at distance rho from the centre in direction angle phi in the disk's plane. */
    private double[] inPlane(double rho, double phi) {
        double[] p = new double[3];
        double[] c = {centre.x(), centre.y(), centre.z()};
        for (int k = 0; k < 3; k++) {
            p[k] = c[k] + rho * (Math.cos(phi) * a[k] + Math.sin(phi) * b[k]);
        }
        return p;
    }

    @Test
    void raysAlongTheNormalHitInsideTheRadiusAndMissOutside() {
        SplittableRandom random = new SplittableRandom(9);
        for (int i = 0; i < 500; i++) {
            double phi = random.nextDouble(0, 2 * Math.PI);
            double rho = 1.5 * Math.sqrt(random.nextDouble());
            double[] p = inPlane(rho, phi);
            // from 4 units in front of the point, straight back along -n: t = 4
            ShadeRec sr = h.hit(disk, ray(p[0] + 4 * n[0], p[1] + 4 * n[1], p[2] + 4 * n[2], -n[0], -n[1], -n[2]));
            assertNotNull(sr, "rho " + rho);
            assertEquals(4, sr.t, 1e-12);
            assertEquals(p[0], sr.hitPoint.x, 1e-12);
            assertEquals(p[1], sr.hitPoint.y, 1e-12);
            assertEquals(p[2], sr.hitPoint.z, 1e-12);
            assertEquals(n[0], sr.normal.x, 1e-15);
            assertEquals(n[1], sr.normal.y, 1e-15);
            assertEquals(n[2], sr.normal.z, 1e-15);
            assertTrue(sr.frontFace);
            assertEquals(rho / 1.5, sr.u, 1e-12, "u is the distance from the centre over the radius");
            assertEquals(0, sr.v, 0);
        }
        for (double rho : new double[] {1.5 * (1 - 1e-9), 1.5 * (1 + 1e-9)}) {
            double[] p = inPlane(rho, 1.0);
            boolean hit = h.hit(disk, ray(p[0] + 4 * n[0], p[1] + 4 * n[1], p[2] + 4 * n[2], -n[0], -n[1], -n[2])) != null;
            assertEquals(rho < 1.5, hit, "rho " + rho);
        }
    }

    @Test
    void anObliqueRayHitsAtThePlaneDistanceAndFromBehindTheNormalTurns() {
        // from o along d: t = n.(c - o) / n.d; here from behind the disk, through the point at rho 1
        double[] p = inPlane(1, 2.0);
        double[] d = {0.2, -0.9, -0.3};
        double[] o = {p[0] - 5 * d[0], p[1] - 5 * d[1], p[2] - 5 * d[2]};
        double nd = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        assertTrue(nd < 0, "the ray comes from the front");
        ShadeRec front = h.hit(disk, ray(o[0], o[1], o[2], d[0], d[1], d[2]));
        assertNotNull(front);
        assertEquals(5, front.t, 1e-12);
        double[] back = {p[0] + 5 * d[0], p[1] + 5 * d[1], p[2] + 5 * d[2]};
        ShadeRec sr = h.hit(disk, ray(back[0], back[1], back[2], -d[0], -d[1], -d[2]));
        assertNotNull(sr);
        assertEquals(5, sr.t, 1e-12);
        assertFalse(sr.frontFace);
        assertEquals(-n[0], sr.normal.x, 1e-15);
        assertEquals(-n[2], sr.normal.z, 1e-15);
        assertTrue(h.shadowHit(disk, ray(o[0], o[1], o[2], d[0], d[1], d[2]), 5.5));
        assertFalse(h.shadowHit(disk, ray(o[0], o[1], o[2], d[0], d[1], d[2]), 4.5));
    }

    @Test
    void raysParallelToTheDiskMiss() {
        double[] p = inPlane(0.5, 0.3);
        assertNull(h.hit(disk, ray(p[0] - 3 * a[0], p[1] - 3 * a[1], p[2] - 3 * a[2], a[0], a[1], a[2])), "in its plane");
        assertNull(h.hit(disk, ray(p[0] + n[0], p[1] + n[1], p[2] + n[2], a[0], a[1], a[2])), "above it");
    }

    @Test
    void aGridOfRaysSeesTheDisksArea() {
        // rays along -n through a 400 x 400 grid over the square of side 3 around the disk: the
        // fraction that hits is pi r^2 / 9 = pi / 4, up to the grid's resolution along the rim
        int hits = 0;
        int side = 400;
        for (int i = 0; i < side; i++) {
            for (int j = 0; j < side; j++) {
                double s = -1.5 + 3 * (i + 0.5) / side;
                double t = -1.5 + 3 * (j + 0.5) / side;
                double[] p = {centre.x() + s * a[0] + t * b[0] + 2 * n[0], centre.y() + s * a[1] + t * b[1] + 2 * n[1],
                              centre.z() + s * a[2] + t * b[2] + 2 * n[2]};
                hits += h.shadowHit(disk, ray(p[0], p[1], p[2], -n[0], -n[1], -n[2]), 3) ? 1 : 0;
            }
        }
        assertEquals(Math.PI / 4, (double) hits / (side * side), 2e-3);
    }

    @Test
    void theBoundingBoxHoldsTheRimAndTouchesIt() {
        // per axis the rim reaches r sqrt(1 - n_k^2) from the centre: (1.5 sqrt(8)/3, 1.5 sqrt(5)/3, 1.5 sqrt(5)/3)
        BBox box = disk.boundingBox();
        double[] lo = {box.x0(), box.y0(), box.z0()};
        double[] hi = {box.x1(), box.y1(), box.z1()};
        double[] c = {centre.x(), centre.y(), centre.z()};
        double[] reach = {1.5 * Math.sqrt(8) / 3, 1.5 * Math.sqrt(5) / 3, 1.5 * Math.sqrt(5) / 3};
        double[] farthest = new double[3];
        for (int i = 0; i < 100_000; i++) {
            double[] p = inPlane(1.5, 2 * Math.PI * i / 100_000);
            for (int k = 0; k < 3; k++) {
                assertTrue(p[k] >= lo[k] - 1e-12 && p[k] <= hi[k] + 1e-12, "rim point outside the box on axis " + k);
                farthest[k] = Math.max(farthest[k], Math.abs(p[k] - c[k]));
            }
        }
        for (int k = 0; k < 3; k++) {
            assertEquals(reach[k], hi[k] - c[k], 1e-12, "axis " + k);
            assertEquals(reach[k], c[k] - lo[k], 1e-12, "axis " + k);
            assertEquals(reach[k], farthest[k], 1e-8, "the rim touches the box on axis " + k);
        }
    }

    @Test
    void badDisksAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new Disk(centre, new Vector3D(0, 0, 0), 1));
        assertThrows(IllegalArgumentException.class, () -> new Disk(centre, new Vector3D(0, 1, 0), 0));
        assertThrows(IllegalArgumentException.class, () -> new Disk(new Point3D(Double.NaN, 0, 0), new Vector3D(0, 1, 0), 1));
    }

    @Test
    void grazingRaysHitTheFaceTheyComeFrom() {
        h.assertGrazingFaces(disk, inPlane(0.5, 0.3), n, a);
        h.assertGrazingFaces(disk, inPlane(1.2, 2), n, b);
    }
}

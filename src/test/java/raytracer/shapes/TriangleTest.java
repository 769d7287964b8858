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
import raytracer.math.Point3D;

class TriangleTest {
    private final HitTesting h = new HitTesting();
    private final Triangle tri = new Triangle(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0));

    @Test
    void interiorHitHasBarycentricsAndTheFaceNormal() {
        ShadeRec sr = h.hit(tri, ray(0.25, 0.5, 2, 0, 0, -1));
        assertNotNull(sr);
        assertEquals(2, sr.t, 1e-15);
        assertEquals(0.25, sr.u, 1e-15);
        assertEquals(0.5, sr.v, 1e-15);
        assertEquals(1, sr.normal.z, 0);
        assertEquals(0.25, sr.hitPoint.x, 1e-15);
    }

    @Test
    void edgesAndVerticesAreHit() {
        double[][] points = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0, 0.5}, {0.5, 0.5}};
        for (double[] p : points) {
            assertNotNull(h.hit(tri, ray(p[0], p[1], 1, 0, 0, -1)), "missed (" + p[0] + ", " + p[1] + ")");
        }
        assertNull(h.hit(tri, ray(0.5 + 1e-12, 0.5 + 1e-12, 1, 0, 0, -1)));
        assertNull(h.hit(tri, ray(-1e-12, 0.5, 1, 0, 0, -1)));
    }

    @Test
    void bothSidesAreHitAndTheNormalFacesTheRay() {
        ShadeRec sr = h.hit(tri, ray(0.2, 0.2, -1, 0, 0, 1));
        assertNotNull(sr);
        assertFalse(sr.frontFace);
        assertEquals(-1, sr.normal.z, 0);
    }

    @Test
    void edgeOnRayMisses() {
        assertNull(h.hit(tri, ray(-1, 0.2, 0, 1, 0, 0)));
    }

    @Test
    void degenerateTrianglesNeverHitAndNeverGiveNaN() {
        Triangle[] degenerate = {
            new Triangle(new Point3D(0, 0, 0), new Point3D(1, 1, 1), new Point3D(2, 2, 2)),
            new Triangle(new Point3D(0, 0, 0), new Point3D(0, 0, 0), new Point3D(0, 1, 0)),
            new Triangle(new Point3D(1, 1, 1), new Point3D(1, 1, 1), new Point3D(1, 1, 1)),
            new Triangle(new Point3D(0, 0, 0), new Point3D(1e-3, 1e-3, 0), new Point3D(1e6, 1e6, 0)),
        };
        SplittableRandom random = new SplittableRandom(3);
        for (Triangle d : degenerate) {
            assertTrue(d.boundingBox().isBounded());
            for (int i = 0; i < 10_000; i++) {
                double ox = random.nextDouble(-3, 3);
                double oy = random.nextDouble(-3, 3);
                double oz = random.nextDouble(-3, 3);
                double tx = random.nextDouble(0, 2);
                double tz = random.nextDouble(-0.01, 0.01);
                assertNull(h.hit(d, ray(ox, oy, oz, tx - ox, tx - oy, tz - oz)));
                assertFalse(h.shadowHit(d, ray(ox, oy, oz, tx - ox, tx - oy, tz - oz), Double.POSITIVE_INFINITY));
            }
        }
    }

    @Test
    void grazingRaysHitTheFaceTheyComeFrom() {
        // a miss is allowed at slope 1e-14, within the test's bound on t of the ray's start
        h.assertGrazingFaces(tri, new double[] {0.25, 0.25, 0}, new double[] {0, 0, 1}, new double[] {1, 0, 0}, 1e-10);
        double s = Math.sqrt(0.5);
        Triangle tilted = new Triangle(new Point3D(0, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 0, 1));
        h.assertGrazingFaces(tilted, new double[] {0.25, 0.25, 0.5}, new double[] {s, -s, 0}, new double[] {s, s, 0}, 1e-10);
    }
}

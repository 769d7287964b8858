package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/** The parallelogram of a rectangle light: its coordinates, its edges and its faces. */
class RectangleTest {
    private final HitTesting h = new HitTesting();
    /** Corner (1, 2, 3), edges (2, 0, 0) and (0, 0, -1): the normal a x b is (0, 2, 0) / 2. */
    private final Rectangle rectangle = new Rectangle(new Point3D(1, 2, 3), new Vector3D(2, 0, 0), new Vector3D(0, 0, -1));

    @Test
    void aHitHasItsEdgeCoordinatesAndTheNormalOfAxB() {
        ShadeRec sr = h.hit(rectangle, ray(1.5, 5, 2.75, 0, -1, 0));
        assertNotNull(sr);
        assertEquals(3, sr.t, 0);
        assertEquals(0.25, sr.u, 1e-15);
        assertEquals(0.25, sr.v, 1e-15);
        assertTrue(sr.frontFace);
        assertEquals(1, sr.normal.y, 0);
        assertNull(h.hit(rectangle, ray(3.5, 5, 2.75, 0, -1, 0)), "past edge a");
        assertNull(h.hit(rectangle, ray(1.5, 5, 1.5, 0, -1, 0)), "past edge b");
    }

    @Test
    void grazingRaysHitTheFaceTheyComeFrom() {
        h.assertGrazingFaces(rectangle, new double[] {1.5, 2, 2.5}, new double[] {0, 1, 0}, new double[] {1, 0, 0});
        double s = Math.sqrt(0.5);
        Rectangle tilted = new Rectangle(new Point3D(0, 0, 0), new Vector3D(1, 1, 0), new Vector3D(0, 0, 1));
        h.assertGrazingFaces(tilted, new double[] {0.5, 0.5, 0.5}, new double[] {s, -s, 0}, new double[] {s, s, 0});
    }
}

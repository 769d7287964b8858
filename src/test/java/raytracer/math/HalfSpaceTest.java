package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Inside means n . p &lt;= d for every corner; excluded means past the plane by more than the margin, at any scale. */
class HalfSpaceTest {
    @Test
    void boxesInsideOutsideAndAcross() {
        HalfSpace below = new HalfSpace(0, 1, 0, 2); // y <= 2
        assertTrue(below.contains(new BBox(-5, -1, -5, 5, 2, 5)), "touching the plane is inside");
        assertFalse(below.contains(new BBox(-5, -1, -5, 5, 2.5, 5)));
        assertTrue(below.excludes(new BBox(-5, 2.5, -5, 5, 3, 5)));
        assertFalse(below.excludes(new BBox(-5, 2, -5, 5, 3, 5)), "touching is not outside");
        assertFalse(below.excludes(new BBox(-5, 1, -5, 5, 3, 5)), "across");
        BBox unbounded = new BBox(Double.NEGATIVE_INFINITY, 3, 0, Double.POSITIVE_INFINITY, 4, 1);
        assertFalse(below.excludes(unbounded), "an unbounded box is never proved outside");
        assertFalse(below.contains(unbounded));
        HalfSpace slanted = HalfSpace.through(1, 1, 1, 1, 1, 1); // x + y + z <= 3
        assertTrue(slanted.contains(1, 1, 1));
        assertTrue(slanted.excludes(new BBox(1.01, 1, 1, 2, 2, 2)));
        assertFalse(slanted.excludes(new BBox(0.99, 1, 1, 2, 2, 2)));
    }

    @Test
    void theMarginScalesWithTheCoordinates() {
        for (double scale = 1e-4; scale <= 1e6; scale *= 10) {
            HalfSpace h = new HalfSpace(1, 0, 0, scale); // x <= scale
            double gap = scale * 1e-6;
            assertTrue(h.excludes(new BBox(scale + gap, 0, 0, 2 * scale, scale, scale)), "1e-6 relative is past the margin");
            double within = scale * 1e-12;
            assertFalse(h.excludes(new BBox(scale + within, 0, 0, 2 * scale, scale, scale)), "1e-12 relative is rounding");
        }
        assertThrows(IllegalArgumentException.class, () -> new HalfSpace(0, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new HalfSpace(1, 0, Double.NaN, 1));
    }
}

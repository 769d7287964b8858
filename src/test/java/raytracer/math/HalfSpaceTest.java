package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
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

    /**
     * A plane through a far point, whose n . p cancels near the origin: its d was rounded at the
     * point's size, so a box near the origin just past it is not excluded until it clears that
     * size's margin; atScale raises the size, flipped keeps it.
     */
    @Test
    void theMarginAlsoScalesWithTheSizeTheOffsetCameFrom() {
        HalfSpace far = HalfSpace.through(1e8, 0, -1e8, 1, 0, 1); // x + z <= 0, from a point 1e8 away
        assertEquals(1e8, far.size());
        BBox near = new BBox(1e-3, 0, 0, 1, 1, 1); // x + z >= 1e-3
        assertFalse(far.excludes(near), "1e-3 past a plane computed from coordinates of 1e8 is within its margin");
        assertTrue(new HalfSpace(1, 0, 1, 0).excludes(near), "past an exact plane by 1e-3 at coordinates of 1 is outside");
        assertFalse(new HalfSpace(1, 0, 1, 0).atScale(1e8).excludes(near));
        assertEquals(1e8, far.flipped().size());
        // its margin is 2^-30 of 2e8, 0.19: 2 past the flipped plane is outside, 0.1 past is not
        assertTrue(far.flipped().excludes(new BBox(-2, -1, -2, -1, 1, -1)));
        assertFalse(far.flipped().excludes(new BBox(-0.05, -1, -0.05, 0, 1, -0.05)));
        assertTrue(new HalfSpace(0, -1, 0, 3).isAxisAligned());
        assertFalse(far.isAxisAligned());
        assertThrows(IllegalArgumentException.class, () -> new HalfSpace(1, 0, 0, 0, -1));
    }
}

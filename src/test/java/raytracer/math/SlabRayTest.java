package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The slab test's entry distance into the unit cube [0, 1]^3, worked by hand. */
class SlabRayTest {
    private static final float[] CUBE = {0, 0, 0, 1, 1, 1};
    private static final double MISS = Double.POSITIVE_INFINITY;

    private static double entry(double ox, double oy, double oz, double dx, double dy, double dz, double tMax) {
        return new SlabRay().load(new Ray().set(ox, oy, oz, dx, dy, dz)).entry(CUBE, 0, tMax);
    }

    @Test
    void aRayEntersWhereItHasCrossedItsLastNearPlane() {
        assertEquals(2, entry(-2, 0.5, 0.5, 1, 0, 0.1, MISS), 1e-15);
        // inside the y slab from t = 0.5, the z slab from t = 1
        assertEquals(1, entry(0.5, 1.5, -2, 0, -1, 2, MISS), 1e-15);
        assertEquals(1, entry(0.5, 1.5, -2, 0, -1, 2, 1.2), 1e-15, "inside until 1.5, so a tMax of 1.2 still meets it");
    }

    @Test
    void fromInsideTheEntryIsZeroAndBeyondTMaxItIsAMiss() {
        assertEquals(0, entry(0.5, 0.5, 0.5, 1, -1, 0.3, MISS));
        assertEquals(MISS, entry(-2, 0.5, 0.5, 1, 0, 0, 1.5), "the cube starts at t = 2");
        assertEquals(MISS, entry(-2, 0.5, 0.5, -1, 0, 0, MISS), "pointing away");
        assertEquals(MISS, entry(-2, 1.5, 0.5, 1, 0, 0, MISS), "passing beside");
    }

    /**
     * A ray parallel to the y planes with its origin on one: (0 - 0) * 1/0 = 0 * infinity = NaN,
     * which must impose no constraint rather than cull the box; -0.0 direction components alike.
     */
    @Test
    void aRayParallelToAFaceAndStartingInItsPlaneStillEnters() {
        assertEquals(2, entry(-2, 0, 0.5, 1, 0, 0, MISS));
        assertEquals(2, entry(-2, 1, 0.5, 1, -0.0, 0, MISS));
        assertEquals(2, entry(-2, 0.5, 0, 1, 0, -0.0, MISS));
        assertEquals(MISS, entry(-2, 1.5, 0.5, 1, 0, 0, MISS), "parallel and beside it");
    }
}

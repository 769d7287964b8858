package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.PropertyCheck;

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

    /**
     * The slab test takes its extremes on the doubles' bit patterns as longs (SlabRay.entry): the
     * entry it returns must equal, bit for bit, the one of the textbook formulation with
     * Math.max/min, on boxes in front, behind, around the origin and touching it, with zero
     * direction components of either sign, at every scale.
     */
    @Test
    void theBitPatternExtremesGiveTheTextbookEntryExactly() {
        PropertyCheck.forAll("slab entry = textbook entry", 20_000, random -> {
            double scale = PropertyCheck.logUniform(random, 1e-4, 1e6);
            double[] d = PropertyCheck.unitVector(random);
            for (int k = 0; k < 3; k++) {
                if (random.nextInt(8) == 0) {
                    d[k] = random.nextBoolean() ? 0.0 : -0.0;
                }
            }
            // origins representable as floats, so that a plane can pass through one exactly
            double[] o = {(float) coordinate(random, scale), (float) coordinate(random, scale),
                          (float) coordinate(random, scale)};
            float[] box = new float[6];
            for (int k = 0; k < 3; k++) {
                float a = (float) coordinate(random, scale);
                float b = random.nextInt(3) == 0 ? (float) o[k] : (float) coordinate(random, scale);
                box[k] = Math.min(a, b);
                box[k + 3] = Math.max(a, b);
            }
            double tMax = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : PropertyCheck.logUniform(random, 1e-6, 1e8) * scale;
            Ray ray = new Ray().set(o[0], o[1], o[2], d[0], d[1], d[2]);
            double expected = textbookEntry(ray, box, tMax);
            double actual = new SlabRay().load(ray).entry(box, 0, tMax);
            assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                         () -> "entry " + actual + " for the textbook's " + expected);
        });
    }

    private static double coordinate(SplittableRandom random, double scale) {
        return random.nextDouble(-2, 2) * scale;
    }

    /**
     * Kay and Kajiya's test as the textbooks write it, with the same widened far distances and the
     * same rule for NaN (an origin on the plane of a slab the ray runs parallel to imposes nothing).
     */
    private static double textbookEntry(Ray ray, float[] box, double tMax) {
        double widen = 1 + 2 * Rounding.gamma(3);
        double[] o = {ray.ox, ray.oy, ray.oz};
        double[] d = {ray.dx, ray.dy, ray.dz};
        double t0 = 0;
        double t1 = tMax;
        for (int k = 0; k < 3; k++) {
            double inv = 1 / d[k];
            double near = inv < 0 ? box[k + 3] : box[k];
            double far = inv < 0 ? box[k] : box[k + 3];
            double tNear = (near - o[k]) * inv;
            double tFar = (far - o[k]) * (inv * widen);
            if (!Double.isNaN(tNear)) {
                t0 = Math.max(t0, tNear);
            }
            if (!Double.isNaN(tFar)) {
                t1 = Math.min(t1, tFar);
            }
        }
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }
}

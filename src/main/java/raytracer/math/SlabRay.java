package raytracer.math;

/**
 * A ray prepared for slab tests against many boxes (Kay and Kajiya 1986): a box is entered where
 * the ray has entered all three slabs between its planes, and left where it leaves the first.
 * Holds what every test of the ray reuses: the origin, 1/d, 1/d widened for the far planes so that
 * rounding never culls a box the ray touches (pbrt-v3, section 3.9.2), and which plane of each
 * slab the ray meets first. A BVH traversal fills it from its ray when it starts ({@link #load});
 * nothing else writes it, so it cannot go stale while the traversal runs.
 */
public final class SlabRay {
    /** Far slab distances are widened by this factor: gamma(3) covers the subtraction, product and rounding. */
    private static final double WIDEN = 1 + 2 * Rounding.gamma(3);

    private double ox;
    private double oy;
    private double oz;
    private double invX;
    private double invY;
    private double invZ;
    private double farInvX;
    private double farInvY;
    private double farInvZ;
    /** Per axis, the offset (0 or 3) of the near plane in a box stored as x0, y0, z0, x1, y1, z1. */
    private int nearX;
    private int nearY;
    private int nearZ;
    /** True when 1/d is infinite on some axis: the test must then ignore the NaN of 0 * infinity. */
    private boolean parallel;

    /** Prepares the tests of {@code ray}. */
    public SlabRay load(Ray ray) {
        ox = ray.ox;
        oy = ray.oy;
        oz = ray.oz;
        invX = 1.0 / ray.dx;
        invY = 1.0 / ray.dy;
        invZ = 1.0 / ray.dz;
        farInvX = invX * WIDEN;
        farInvY = invY * WIDEN;
        farInvZ = invZ * WIDEN;
        // by the sign of 1/d, not of d: a component -0.0 has 1/d = -infinity, so its near plane is the high one
        nearX = invX < 0 ? 3 : 0;
        nearY = invY < 0 ? 3 : 0;
        nearZ = invZ < 0 ? 3 : 0;
        parallel = !(Math.abs(farInvX) <= Double.MAX_VALUE && Math.abs(farInvY) <= Double.MAX_VALUE
                     && Math.abs(farInvZ) <= Double.MAX_VALUE);
        return this;
    }

    /**
     * The distance at which the ray enters the box stored as floats x0, y0, z0, x1, y1, z1 at
     * {@code box[at .. at + 6)}, clamped to 0 when it starts inside; +infinity when it misses the
     * box on (0, tMax).
     */
    public double entry(float[] box, int at, double tMax) {
        // distance to the near and the far plane of each slab
        double tx0 = (box[at + nearX] - ox) * invX;
        double tx1 = (box[at + 3 - nearX] - ox) * farInvX;
        double ty0 = (box[at + 1 + nearY] - oy) * invY;
        double ty1 = (box[at + 4 - nearY] - oy) * farInvY;
        double tz0 = (box[at + 2 + nearZ] - oz) * invZ;
        double tz1 = (box[at + 5 - nearZ] - oz) * farInvZ;
        if (parallel) {
            return overlapIgnoringNaN(tx0, tx1, ty0, ty1, tz0, tz1, tMax);
        }
        // inside all three slabs and (0, tMax) from the last entry to the first exit; Math.max/min
        // have no branches, where ordered comparisons would be mispredicted ones
        double t0 = Math.max(Math.max(tx0, ty0), Math.max(tz0, 0));
        double t1 = Math.min(Math.min(tx1, ty1), Math.min(tz1, tMax));
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    /**
     * {@link #entry}'s overlap for rays parallel to an axis: an origin on a plane of that slab gives
     * 0 * infinity = NaN, which Math.max would spread; here a NaN fails its comparison and imposes
     * no constraint.
     */
    private static double overlapIgnoringNaN(double tx0, double tx1, double ty0, double ty1, double tz0, double tz1,
                                             double tMax) {
        // a method of its own: most renders never call it, so the JIT leaves it out of the traversal
        double t0 = tx0 > 0 ? tx0 : 0;
        double t1 = tx1 < tMax ? tx1 : tMax;
        t0 = ty0 > t0 ? ty0 : t0;
        t1 = ty1 < t1 ? ty1 : t1;
        t0 = tz0 > t0 ? tz0 : t0;
        t1 = tz1 < t1 ? tz1 : t1;
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }
}

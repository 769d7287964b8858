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
        // the six planes read at fixed offsets, so that the JIT checks the array bounds once for
        // all of them; which of each pair is near is the ray's, so those choices predict well
        float x0 = box[at];
        float y0 = box[at + 1];
        float z0 = box[at + 2];
        float x1 = box[at + 3];
        float y1 = box[at + 4];
        float z1 = box[at + 5];
        // distance to the near and the far plane of each slab; + 0.0 makes an exit of -0.0 (an
        // origin on a far plane) +0.0, for the extremes below
        double tx0 = ((nearX == 0 ? x0 : x1) - ox) * invX;
        double tx1 = ((nearX == 0 ? x1 : x0) - ox) * farInvX + 0.0;
        double ty0 = ((nearY == 0 ? y0 : y1) - oy) * invY;
        double ty1 = ((nearY == 0 ? y1 : y0) - oy) * farInvY + 0.0;
        double tz0 = ((nearZ == 0 ? z0 : z1) - oz) * invZ;
        double tz1 = ((nearZ == 0 ? z1 : z0) - oz) * farInvZ + 0.0;
        if (parallel) {
            return overlapIgnoringNaN(tx0, tx1, ty0, ty1, tz0, tz1, tMax);
        }
        // inside all three slabs and (0, tMax) from the last entry to the first exit. The extremes
        // are taken on the bit patterns as longs: no NaN arises here, a double >= +0.0 orders as
        // its pattern does, and a negative one (-0.0 aside) has a negative pattern. So the largest
        // entry clamped at 0 is exact, and the smallest exit is exact or negative when one exit
        // is negative, which is a miss either way. Math.max(long) is a conditional move, where
        // Math.max(double) spends a blend sequence on NaN and -0.0 rules (the traversal ran 1.35
        // times as fast without it, docs/performance.md), and comparisons of doubles would be
        // mispredicted branches.
        double t0 = Double.longBitsToDouble(Math.max(Math.max(bits(tx0), bits(ty0)), Math.max(bits(tz0), 0L)));
        double t1 = Double.longBitsToDouble(Math.min(Math.min(bits(tx1), bits(ty1)), Math.min(bits(tz1), bits(tMax))));
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
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

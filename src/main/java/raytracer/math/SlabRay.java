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
    /** Per axis, the offsets of the near and the far plane of a box in a group of four stored plane by plane ({@link #entryBits}). */
    private int xNear;
    private int xFar;
    private int yNear;
    private int yFar;
    private int zNear;
    private int zFar;
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
        xNear = 4 * nearX;
        xFar = 12 - xNear;
        yNear = 4 + 4 * nearY;
        yFar = 20 - yNear;
        zNear = 8 + 4 * nearZ;
        zFar = 28 - zNear;
        parallel = !(Math.abs(farInvX) <= Double.MAX_VALUE && Math.abs(farInvY) <= Double.MAX_VALUE
                     && Math.abs(farInvZ) <= Double.MAX_VALUE);
        return this;
    }

    /** The origin's coordinate on axis 0, 1 or 2: what a test of several boxes at once ({@link #entryBits}'s arithmetic, lane by lane) reads. */
    public double origin(int axis) {
        return axis == 0 ? ox : axis == 1 ? oy : oz;
    }

    /** 1/d on the axis, for the near planes. */
    public double inverse(int axis) {
        return axis == 0 ? invX : axis == 1 ? invY : invZ;
    }

    /** 1/d widened, for the far planes. */
    public double farInverse(int axis) {
        return axis == 0 ? farInvX : axis == 1 ? farInvY : farInvZ;
    }

    /** The offset of the axis's near plane in a group of four boxes stored plane by plane ({@link #entryBits}). */
    public int nearPlane(int axis) {
        return axis == 0 ? xNear : axis == 1 ? yNear : zNear;
    }

    /** The offset of the axis's far plane, as {@link #nearPlane}. */
    public int farPlane(int axis) {
        return axis == 0 ? xFar : axis == 1 ? yFar : zFar;
    }

    /** True when 1/d is infinite on some axis, where a test must ignore the NaN of 0 * infinity ({@link #entryBits} does). */
    public boolean parallel() {
        return parallel;
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

    /**
     * {@link #entry} for one of four boxes stored plane by plane (a wide BVH node): its x0 at
     * {@code boxes[at]}, y0 four floats on, then z0, x1, y1, z1, each four on. Returns the entry's
     * bits, or +infinity's bits when the ray misses the box on (0, tMax), {@code tMaxBits} being
     * tMax's bits. The same arithmetic as {@link #entry}, to the bit, without a branch that
     * depends on the box: the extremes are taken on the bit patterns as longs with masks, since
     * the JIT compiles Math.max(long) as a branch or a conditional move by how the program has
     * called it so far, and a branch taken at random costs more than the whole test.
     */
    public long entryBits(float[] boxes, int at, long tMaxBits) {
        // kept under the JIT's inlining limit for hot methods (325 bytes of bytecode): the rare
        // case and the planes' offsets are elsewhere
        if (parallel) {
            return entryBitsIgnoringNaN(boxes, at, tMaxBits);
        }
        long tx0 = bits((boxes[at + xNear] - ox) * invX);
        long tx1 = bits((boxes[at + xFar] - ox) * farInvX + 0.0);
        long ty0 = bits((boxes[at + yNear] - oy) * invY);
        long ty1 = bits((boxes[at + yFar] - oy) * farInvY + 0.0);
        long tz0 = bits((boxes[at + zNear] - oz) * invZ);
        long tz1 = bits((boxes[at + zFar] - oz) * farInvZ + 0.0);
        // the largest entry clamped at 0: negative patterns made 0, then the largest of patterns
        // at most +infinity's, whose differences cannot overflow
        long t0 = maxOfNonNegative(maxOfNonNegative(atLeastZero(tx0), atLeastZero(ty0)), atLeastZero(tz0));
        // the smallest exit: a negative one made -1, below every entry, so the box is missed
        long t1 = minAboveMinusOne(minAboveMinusOne(negativeToMinusOne(tx1), negativeToMinusOne(ty1)),
                                   minAboveMinusOne(negativeToMinusOne(tz1), tMaxBits));
        // t1 < t0 as longs exactly when the doubles are (as in entry: no NaN, no -0.0 here)
        long missed = (t1 - t0) >> 63;
        return t0 & ~missed | INFINITY_BITS & missed;
    }

    private long entryBitsIgnoringNaN(float[] boxes, int at, long tMaxBits) {
        double x0 = boxes[at + xNear];
        double x1 = boxes[at + xFar];
        double y0 = boxes[at + yNear];
        double y1 = boxes[at + yFar];
        double z0 = boxes[at + zNear];
        double z1 = boxes[at + zFar];
        return bits(overlapIgnoringNaN((x0 - ox) * invX, (x1 - ox) * farInvX + 0.0, (y0 - oy) * invY, (y1 - oy) * farInvY + 0.0,
                                       (z0 - oz) * invZ, (z1 - oz) * farInvZ + 0.0, Double.longBitsToDouble(tMaxBits)));
    }

    private static final long INFINITY_BITS = Double.doubleToRawLongBits(Double.POSITIVE_INFINITY);

    /** x, or 0 when x is negative. */
    private static long atLeastZero(long x) {
        return x & ~(x >> 63);
    }

    /** x, or -1 when x is negative. */
    private static long negativeToMinusOne(long x) {
        return x | x >> 63;
    }

    /** The larger of a and b, both in [0, 2^63 - 1), without a branch. */
    private static long maxOfNonNegative(long a, long b) {
        long d = a - b;
        return a - (d & d >> 63);
    }

    /** The smaller of a and b, both in [-1, +infinity's bits], without a branch. */
    private static long minAboveMinusOne(long a, long b) {
        long d = a - b;
        return b + (d & d >> 63);
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

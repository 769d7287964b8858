package raytracer.math;

/** The ray/box slab test (Kay and Kajiya 1986) in its conservative form. */
public final class Slabs {
    private static final double ROUNDING = 1 + 2 * Rounding.gamma(3);

    private Slabs() {
    }

    /**
     * The distance at which the ray enters the box stored as six float bit patterns
     * (x0, y0, z0, x1, y1, z1) in {@code b[i..i+6)} (a packed BVH node), clamped to 0 when it starts
     * inside, or +infinity when it misses the box on (0, tMax). Near and far planes are picked by
     * the direction's sign, so no swap is needed. As in pbrt-v3 section 3.9.2, each far distance is
     * widened by 1 + 2 gamma(3) so rounding never culls a box the ray touches, and the comparisons
     * are ordered so that a NaN (an origin on a slab plane gives 0 * infinity) imposes no
     * constraint instead of rejecting the box.
     */
    public static double entry(int[] b, int i, Ray ray, double tMax) {
        double tx0 = (Float.intBitsToFloat(b[i + ray.nearX]) - ray.ox) * ray.invDx;
        double tx1 = (Float.intBitsToFloat(b[i + 3 - ray.nearX]) - ray.ox) * ray.invDx * ROUNDING;
        double ty0 = (Float.intBitsToFloat(b[i + 1 + ray.nearY]) - ray.oy) * ray.invDy;
        double ty1 = (Float.intBitsToFloat(b[i + 4 - ray.nearY]) - ray.oy) * ray.invDy * ROUNDING;
        double tz0 = (Float.intBitsToFloat(b[i + 2 + ray.nearZ]) - ray.oz) * ray.invDz;
        double tz1 = (Float.intBitsToFloat(b[i + 5 - ray.nearZ]) - ray.oz) * ray.invDz * ROUNDING;
        double t0 = tx0 > 0 ? tx0 : 0;
        double t1 = tx1 < tMax ? tx1 : tMax;
        t0 = ty0 > t0 ? ty0 : t0;
        t1 = ty1 < t1 ? ty1 : t1;
        t0 = tz0 > t0 ? tz0 : t0;
        t1 = tz1 < t1 ? tz1 : t1;
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }
}

package raytracer.math;

/** The ray/box slab test (Kay and Kajiya 1986) in its conservative form. */
public final class Slabs {
    private static final double ROUNDING = 1 + 2 * Rounding.gamma(3);

    private Slabs() {
    }

    /**
     * True when the ray meets the box {@code b[i..i+6)} = (x0, y0, z0, x1, y1, z1) on (0, tMax).
     * As in pbrt-v3 section 3.9.2, each far distance is widened by 1 + 2 gamma(3) so rounding never
     * culls a box the ray touches, and the comparisons are ordered so that a NaN (an origin on a slab
     * plane gives 0 * infinity) imposes no constraint instead of rejecting the box.
     */
    public static boolean overlap(double[] b, int i, Ray ray, double tMax) {
        double t0 = 0;
        double t1 = tMax;
        double near = (b[i] - ray.ox) * ray.invDx;
        double far = (b[i + 3] - ray.ox) * ray.invDx;
        if (near > far) {
            double swap = near;
            near = far;
            far = swap;
        }
        far *= ROUNDING;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
        if (t0 > t1) {
            return false;
        }
        near = (b[i + 1] - ray.oy) * ray.invDy;
        far = (b[i + 4] - ray.oy) * ray.invDy;
        if (near > far) {
            double swap = near;
            near = far;
            far = swap;
        }
        far *= ROUNDING;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
        if (t0 > t1) {
            return false;
        }
        near = (b[i + 2] - ray.oz) * ray.invDz;
        far = (b[i + 5] - ray.oz) * ray.invDz;
        if (near > far) {
            double swap = near;
            near = far;
            far = swap;
        }
        far *= ROUNDING;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
        return t0 <= t1;
    }
}

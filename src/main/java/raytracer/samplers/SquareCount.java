package raytracer.samplers;

/** Patterns built on a k x k grid need a perfect square count: the smallest one not below the request. */
final class SquareCount {
    private SquareCount() {
    }

    static int roundUp(int requested) {
        int k = side(requested);
        return k * k;
    }

    /**
     * The grid side k with k * k = roundUp(n): the smallest k &gt;= 1 with k * k &gt;= n. Counted up
     * rather than taken from a square root: shading asks this for every hit's light sample count,
     * which is small (1 for one sample), and the count costs a few integer steps, not a square
     * root and a rounding.
     */
    static int side(int n) {
        int k = 1;
        while ((long) k * k < n) {
            k++;
        }
        return k;
    }

    /** A value just below 1 stays in [0, 1), guarding the rare rounding of (i + u) / n up to 1. */
    static double clamp(double v) {
        return v < 1 ? v : Math.nextDown(1.0);
    }
}

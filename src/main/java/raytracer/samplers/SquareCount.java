package raytracer.samplers;

/** Patterns built on a k x k grid need a perfect square count: the smallest one not below the request. */
final class SquareCount {
    private SquareCount() {
    }

    static int roundUp(int requested) {
        int k = side(requested);
        return k * k;
    }

    /** The grid side k with k * k = roundUp(n). */
    static int side(int n) {
        int k = (int) Math.ceil(Math.sqrt(Math.max(1, n)));
        while ((k - 1) * (k - 1) >= n && k > 1) {
            k--;
        }
        return k;
    }

    /** A value just below 1 stays in [0, 1), guarding the rare rounding of (i + u) / n up to 1. */
    static double clamp(double v) {
        return v < 1 ? v : Math.nextDown(1.0);
    }
}

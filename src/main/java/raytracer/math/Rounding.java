package raytracer.math;

/**
 * Floating-point error bounds (pbrt-v3, section 3.9): after n correctly rounded operations a value
 * carries a relative error of at most gamma(n) = n u / (1 - n u), with u = 2^-53 for doubles.
 * Shapes use these bounds to say how far a computed hit point may lie off the true surface, and
 * secondary rays start just beyond that bound, whatever the scale of the scene.
 */
public final class Rounding {
    private static final double U = 0x1.0p-53;

    private Rounding() {
    }

    public static double gamma(int n) {
        return (n * U) / (1 - n * U);
    }
}

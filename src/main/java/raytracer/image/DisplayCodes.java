package raytracer.image;

/**
 * The 8-bit codes of {@link ToneMap#toByte(double, double, boolean)} for one exposure and curve,
 * found by comparisons instead of a power per value. The code only grows with the value (the
 * curve, Math.pow included, is monotonic: the Java specification requires pow to be
 * semi-monotonic), so it is fixed by the 255 values where it steps up; they are found once by
 * bisection over the doubles, with toByte itself, and a value's code is then the number of steps
 * at or below it. A table over 4096 equal slices of [0, 1] gives the code at each slice's start,
 * so a lookup makes a few comparisons at most. Codes equal toByte's for every value.
 */
public final class DisplayCodes {
    private static final int SLICES = 4096;

    private final double exposure;
    /** steps[k]: the least value (after exposure) whose code is k, for k = 1 .. 255. */
    private final double[] steps = new double[256];
    private final int[] sliceCodes = new int[SLICES];

    public DisplayCodes(double exposure, boolean srgb) {
        this.exposure = exposure;
        for (int k = 1; k <= 255; k++) {
            steps[k] = leastValueWithCode(k, srgb);
        }
        for (int i = 0; i < SLICES; i++) {
            sliceCodes[i] = ToneMap.toByte((double) i / SLICES, 1, srgb);
        }
    }

    /** The code of a linear radiance, as ToneMap.toByte(linear, exposure, srgb) gives it. */
    public int code(double linear) {
        double v = linear * exposure;
        if (!(v > 0)) {
            return 0; // NaN too, as toByte
        }
        if (v >= 1) {
            return 255;
        }
        int k = sliceCodes[(int) (v * SLICES)];
        while (k < 255 && v >= steps[k + 1]) {
            k++;
        }
        return k;
    }

    /** Bisection over the doubles in [0, 1], which order as their bit patterns do as longs. */
    private static double leastValueWithCode(int k, boolean srgb) {
        long lo = Double.doubleToRawLongBits(0.0); // code 0
        long hi = Double.doubleToRawLongBits(1.0); // code 255 >= k
        while (hi - lo > 1) {
            long mid = lo + (hi - lo) / 2;
            if (ToneMap.toByte(Double.longBitsToDouble(mid), 1, srgb) >= k) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return Double.longBitsToDouble(hi);
    }
}

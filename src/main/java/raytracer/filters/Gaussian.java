package raytracer.filters;

import raytracer.core.PixelFilter;

/**
 * The Gaussian filter, Mitsuba 3's default reconstruction: standard deviation sigma (0.5 pixel by
 * default), cut off at r = 4 sigma, w(d) = exp(-d^2 / (2 sigma^2)) - exp(-r^2 / (2 sigma^2)) so that
 * the weight falls to 0 at the radius instead of jumping there. Each sample counts for the pixels
 * whose centres lie within r of it: pixels share samples (about 4 pi sigma^2 pixels' worth), so
 * each is less noisy, and the image slightly softer (docs/performance.md, "The Gaussian pixel
 * filter", for what that buys against stratified samples).
 */
public final class Gaussian implements PixelFilter {
    public static final double DEFAULT_STDDEV = 0.5;
    /** The narrowest: its radius, 4 sigma, must reach past a pixel's own half width. */
    public static final double MIN_STDDEV = 0.2;
    /**
     * The widest: a sample then reaches 8 pixels each way, 289 pixels in all, within the half tile
     * that the renderer gathers from (render.FilteredImage.check).
     */
    public static final double MAX_STDDEV = 2;
    /**
     * Entries of the weight table: a weight costs a table read and a multiply-add instead of two
     * calls of exp, ten times per sample.
     */
    private static final int TABLE_SIZE = 1024;

    private final double stddev;
    private final double radius;
    /** w at distances i r / TABLE_SIZE, i = 0 .. TABLE_SIZE (the last is 0), for linear interpolation. */
    private final double[] table = new double[TABLE_SIZE + 1];
    /** Table entries per pixel of distance. */
    private final double scale;

    /** True for a standard deviation from {@link #MIN_STDDEV} to {@link #MAX_STDDEV} pixels (NaN is not). */
    public static boolean allows(double stddev) {
        return stddev >= MIN_STDDEV && stddev <= MAX_STDDEV;
    }

    public Gaussian(double stddev) {
        if (!allows(stddev)) {
            throw new IllegalArgumentException("the filter's standard deviation must be " + MIN_STDDEV + " to " + MAX_STDDEV
                                               + " pixels, got " + stddev);
        }
        this.stddev = stddev;
        this.radius = 4 * stddev;
        this.scale = TABLE_SIZE / radius;
        for (int i = 0; i < TABLE_SIZE; i++) {
            table[i] = exactWeight(i * radius / TABLE_SIZE);
        }
    }

    @Override
    public String name() {
        return "gaussian";
    }

    public double stddev() {
        return stddev;
    }

    @Override
    public double radius() {
        return radius;
    }

    @Override
    public double weight(double d) {
        double x = Math.abs(d) * scale;
        if (!(x < TABLE_SIZE)) {
            return 0;
        }
        int i = (int) x;
        double f = x - i;
        return table[i] + f * (table[i + 1] - table[i]);
    }

    /** The weight as the formula gives it, for the table and for tests. */
    public double exactWeight(double d) {
        double alpha = -1 / (2 * stddev * stddev);
        return Math.max(0, Math.exp(alpha * d * d) - Math.exp(alpha * radius * radius));
    }

    @Override
    public String toString() {
        return name() + " (standard deviation " + stddev + " pixel)";
    }
}

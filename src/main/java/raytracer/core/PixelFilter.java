package raytracer.core;

import java.util.List;

/**
 * How a pixel's value is made from the samples around it (pbrt-v3, section 7.8). The book's is the
 * box: a pixel is the plain average of the samples taken inside it (Suffern, listing 4.2). The
 * Gaussian spreads each sample over the pixels whose centres lie within its radius, weighted by
 * w(dx) w(dy), and a pixel is the weighted average of every sample that reaches it: pixels share
 * samples, so each is less noisy, at the price of a slightly softer image. It is the default
 * reconstruction of Mitsuba 3, with whose error figures issue 13 compares: standard deviation
 * 0.5 pixel, cut off at 4 standard deviations, w(d) = exp(-d^2 / (2 sigma^2)) - exp(-r^2 / (2 sigma^2))
 * so that the weight falls to 0 at the radius instead of jumping there.
 */
public final class PixelFilter {
    /** The names a scene or the command line may give. */
    public static final List<String> NAMES = List.of("box", "gaussian");
    /** The book's: each sample counts for its own pixel only, with weight 1. */
    public static final PixelFilter BOX = new PixelFilter("box", 0, 0.5);
    public static final double DEFAULT_STDDEV = 0.5;
    /** The narrowest Gaussian: its radius, 4 sigma, must reach past a pixel's own half width. */
    public static final double MIN_STDDEV = 0.2;
    /**
     * The widest: a sample then reaches 8 pixels each way, 289 pixels in all, still less than a
     * tile's size, so a pixel lies in the margins of at most four tiles (Renderer.resolve).
     */
    public static final double MAX_STDDEV = 2;
    /**
     * Entries of the weight table: a weight costs a table read and a multiply-add instead of two
     * calls of exp, ten times per sample.
     */
    private static final int TABLE_SIZE = 1024;

    private final String name;
    private final double stddev;
    private final double radius;
    /** w at distances i r / TABLE_SIZE, i = 0 .. TABLE_SIZE (the last is 0), for linear interpolation. */
    private final double[] table;
    /** Table entries per pixel of distance. */
    private final double scale;

    private PixelFilter(String name, double stddev, double radius) {
        this.name = name;
        this.stddev = stddev;
        this.radius = radius;
        this.scale = TABLE_SIZE / radius;
        this.table = new double[TABLE_SIZE + 1];
        for (int i = 0; i < TABLE_SIZE; i++) {
            table[i] = exactWeight(i * radius / TABLE_SIZE);
        }
        // the Gaussian falls to 0 at the radius; the box stays 1 up to it
        table[TABLE_SIZE] = isBox() ? 1 : 0;
    }

    /** The Gaussian of standard deviation {@code stddev} pixels, cut off at 4 stddev. */
    public static PixelFilter gaussian(double stddev) {
        if (!(stddev >= MIN_STDDEV && stddev <= MAX_STDDEV)) {
            throw new IllegalArgumentException("the filter's standard deviation must be " + MIN_STDDEV + " to " + MAX_STDDEV
                                               + " pixels, got " + stddev);
        }
        return new PixelFilter("gaussian", stddev, 4 * stddev);
    }

    /** A filter by name ({@link #NAMES}); the Gaussian with {@link #DEFAULT_STDDEV}. */
    public static PixelFilter named(String name) {
        return switch (name) {
            case "box" -> BOX;
            case "gaussian" -> gaussian(DEFAULT_STDDEV);
            default -> throw new IllegalArgumentException("unknown filter '" + name + "'; allowed: " + String.join(", ", NAMES));
        };
    }

    public boolean isBox() {
        return stddev == 0;
    }

    public String name() {
        return name;
    }

    public double stddev() {
        return stddev;
    }

    /** Distance from a pixel's centre, along x or y, beyond which a sample adds nothing to it. */
    public double radius() {
        return radius;
    }

    /**
     * How many pixels beyond its own, each way, a sample may reach: a sample at fraction f of its
     * pixel is |k + 0.5 - f| from the centre k pixels over, which is below the radius for some f
     * exactly when |k| &lt; radius + 0.5.
     */
    public int reach() {
        return (int) Math.ceil(radius + 0.5) - 1;
    }

    /** The weight along one axis of a sample {@code d} pixels from a pixel's centre. */
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
        if (isBox()) {
            return Math.abs(d) < radius ? 1 : 0;
        }
        double alpha = -1 / (2 * stddev * stddev);
        return Math.max(0, Math.exp(alpha * d * d) - Math.exp(alpha * radius * radius));
    }

    @Override
    public String toString() {
        return isBox() ? name : name + " (standard deviation " + stddev + " pixel)";
    }
}

package raytracer.core;

import raytracer.math.Rng;

/**
 * Generates sample points in the unit square (Suffern, chapter 5). The book's sampler keeps sets
 * of points with shuffled indices and a shared counter; here a render keeps its sets in
 * {@link SampleTables}, and a worker's {@link PixelSamples} picks a set and a shuffle for each pixel
 * and dimension by hashing, so that images do not depend on how work is split over threads and no
 * sample's draws shift another's.
 */
public interface Sampler {
    /**
     * The most samples a count may ask for: per pixel, per area light, per glossy reflection.
     * 1024^2, a square, so a pattern on a k x k grid rounds it to itself and no rounding can pass
     * the int range (2^31 - 1 rounded up to 46341^2 overflowed to -2147479015); a render's tables
     * a pattern of that many points then takes 16 MiB in {@link SampleTables}.
     */
    int MAX_SAMPLES = 1 << 20;

    /** The number of samples this pattern really uses for a request of {@code requested}. */
    default int supportedCount(int requested) {
        return requested;
    }

    /** Writes {@code n} points of [0,1)^2 into {@code xs}, {@code ys}; n is a supported count. */
    void generate(int n, Rng rng, double[] xs, double[] ys);

    /**
     * True for sequences whose order carries structure, as in Sobol's, where every aligned block
     * of 2^k points is itself stratified: their patterns are used in order, so that the values one
     * sample takes together form such a block. The book's patterns are shuffled instead.
     */
    default boolean keepsOrder() {
        return false;
    }
}

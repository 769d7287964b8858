package raytracer.core;

import raytracer.math.Rng;

/**
 * Generates sample points in the unit square (Suffern, chapter 5). The book's sampler keeps sets
 * of points with shuffled indices and a shared counter; here a worker's {@link PixelSamples} asks
 * for one set per pixel and dimension (or, from a pointwise sampler, for single points), drawn from
 * a generator seeded by (seed, pixel, dimension), so that images do not depend on how work is split
 * over threads and no sample's draws shift another's.
 */
public interface Sampler {

    /** The number of samples this pattern really uses for a request of {@code requested}. */
    default int supportedCount(int requested) {
        return requested;
    }

    /** Writes {@code n} points of [0,1)^2 into {@code xs}, {@code ys}; n is a supported count. */
    void generate(int n, Rng rng, double[] xs, double[] ys);

    /**
     * True for samplers whose point {@code i} can be computed alone by {@link #point}, a pure
     * function of i and a scramble, without generating the rest of the pattern (sequences such as
     * Sobol's); false for the book's patterns, which are made whole by {@link #generate}.
     */
    default boolean pointwise() {
        return false;
    }

    /**
     * Point {@code index} of the sequence randomised by {@code scramble}, as two 32-bit fractions:
     * x = (bits &gt;&gt;&gt; 32) 2^-32, y = (bits &amp; 0xffffffff) 2^-32. Only for pointwise samplers.
     */
    default long point(int index, long scramble) {
        throw new UnsupportedOperationException(getClass().getSimpleName() + " makes whole patterns only");
    }
}

package raytracer.core;

import raytracer.math.Rng;

/**
 * Generates sample points in the unit square (Suffern, chapter 5). Unlike the book's sampler, which
 * keeps sample sets and a shared counter, this one draws a fresh pattern per pixel from a generator
 * seeded by the pixel, so images do not depend on how work is split over threads.
 */
public interface Sampler {

    /** The number of samples this pattern really uses for a request of {@code requested}. */
    default int supportedCount(int requested) {
        return requested;
    }

    /** Writes {@code n} points of [0,1)^2 into {@code xs}, {@code ys}; n is a supported count. */
    void generate(int n, Rng rng, double[] xs, double[] ys);
}

package raytracer.math;

/**
 * A small mutable random generator (SplitMix64 seeding a 64-bit state, as in Steele, Lea and Flood,
 * "Fast splittable pseudorandom number generators", OOPSLA 2014). It is reseeded, never shared, so
 * that an image does not depend on which thread rendered which tile: the render's sample tables
 * draw each set of points from one seeded by (seed, pattern size, set) ({@code core.SampleTables}),
 * and the renderer reseeds each worker's free generator for every pixel sample from the sample's
 * key ({@code core.PixelSamples.sampleKey}), for the few draws outside the sampled dimensions.
 */
public final class Rng {
    private long state;

    public Rng(long seed) {
        reseed(seed);
    }

    public void reseed(long seed) {
        state = mix(seed);
    }

    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        return mix(state);
    }

    /** Uniform in [0, 1) with 53 random bits. */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    /** Uniform in [0, bound). */
    public int nextInt(int bound) {
        return (int) (((nextLong() >>> 33) * bound) >>> 31);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}

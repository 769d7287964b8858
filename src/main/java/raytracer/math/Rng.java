package raytracer.math;

/**
 * A small mutable random generator (SplitMix64 seeding a 64-bit state, as in Steele, Lea and Flood,
 * "Fast splittable pseudorandom number generators", OOPSLA 2014). The renderer reseeds it per pixel
 * from (seed, pixel) so that an image never depends on which thread rendered which tile.
 */
public final class Rng {
    private long state;

    public Rng(long seed) {
        reseed(seed);
    }

    public void reseed(long seed) {
        state = mix(seed);
    }

    /** Seed for one pixel: a hash of the scene seed and the pixel index, the same on every thread. */
    public static long pixelSeed(long seed, int x, int y) {
        return mix(seed * 0x9E3779B97F4A7C15L + ((long) y << 32 | (x & 0xffffffffL)));
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

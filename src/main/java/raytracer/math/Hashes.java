package raytracer.math;

/**
 * Integer hashes that make sample values a pure function of their coordinates (seed, pixel,
 * sample index, dimension) instead of the state of a generator, so that what one sample draws
 * cannot shift what another one gets.
 */
public final class Hashes {
    private static final long GOLDEN = 0x9E3779B97F4A7C15L;

    private Hashes() {
    }

    /**
     * The 64-bit finaliser of SplitMix64 (Steele, Lea and Flood, OOPSLA 2014; Stafford's mix 13):
     * a bijection whose every output bit depends on every input bit.
     */
    public static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** A hash of two values, not symmetric in them. */
    public static long mix(long a, long b) {
        return mix(a * GOLDEN + b);
    }

    /**
     * Element {@code i} of a random permutation of 0 .. n-1 chosen by {@code seed}, without
     * building the permutation: Kensler's hashed permutation ("Correlated Multi-Jittered
     * Sampling", Pixar Technical Memo 13-01, 2013, section 3): a reversible hash on the smallest
     * power-of-two range holding n, repeated until it lands below n (cycle-walking, fewer than two
     * rounds on average), then rotated by the seed. For 1 &lt;= n &lt;= 2^30.
     */
    public static int permute(int i, int n, int seed) {
        int w = n - 1;
        w |= w >>> 1;
        w |= w >>> 2;
        w |= w >>> 4;
        w |= w >>> 8;
        w |= w >>> 16;
        int p = seed;
        do {
            i ^= p;
            i *= 0xe170893d;
            i ^= p >>> 16;
            i ^= (i & w) >>> 4;
            i ^= p >>> 8;
            i *= 0x0929eb3f;
            i ^= p >>> 23;
            i ^= (i & w) >>> 1;
            i *= 1 | p >>> 27;
            i *= 0x6935fa69;
            i ^= (i & w) >>> 11;
            i *= 0x74dcb303;
            i ^= (i & w) >>> 2;
            i *= 0x9e501cc3;
            i ^= (i & w) >>> 2;
            i *= 0xc860a3df;
            i &= w;
            i ^= i >>> 5;
        } while (i >= n);
        // the rotation taken mod n first: (i + p) would wrap past 2^32 for some seeds and lose a value
        return (i + Integer.remainderUnsigned(p, n)) % n;
    }
}

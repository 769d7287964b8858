package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/**
 * The first two dimensions of Sobol's sequence, Owen-scrambled: a (0,2)-sequence in base 2, so the
 * first 2^m points, and every aligned block of 2^k of them, put one point in each elementary box
 * of area 2^-m (2^-k) of the unit square, whatever its shape (Niederreiter 1992; pbrt-v4, section
 * 8.7). x is the van der Corput radical inverse of i; y applies the generator matrix of Sobol's
 * second dimension (primitive polynomial x + 1: column k is v_k = v_(k-1) xor v_(k-1) / 2, the
 * Pascal matrix mod 2). Owen's scrambling (1995) flips each digit by a random function of the
 * digits above it; it keeps the boxes' one point each and makes every point uniform over the
 * square, so the estimates are unbiased. Computed by hashing (Laine and Karras 2011, with the
 * constants of Vegdahl 2021, as in Burley, "Practical Hash-based Owen Scrambling", JCGT 2020).
 */
public final class Sobol implements Sampler {
    /** Column k of the second dimension's generator matrix, with its bits reversed (digit 1 lowest). */
    private static final int[] REVERSED_COLUMNS = new int[32];

    static {
        int v = 1 << 31;
        for (int k = 0; k < 32; k++) {
            REVERSED_COLUMNS[k] = Integer.reverse(v);
            v ^= v >>> 1;
        }
    }

    /** Blocks of 2^k consecutive points are stratified: kept in order, not shuffled. */
    @Override
    public boolean keepsOrder() {
        return true;
    }

    /**
     * Point {@code index} of the sequence, x scrambled with the low 32 bits of {@code scramble} and
     * y with the high ones, as two 32-bit fractions: x in the high half of the result.
     */
    static long point(int index, long scramble) {
        // the van der Corput value of i is i with its bits reversed, so reversed it is i itself
        int x = owen(index, (int) scramble);
        int y = owen(secondDimensionReversed(index), (int) (scramble >>> 32));
        return (long) x << 32 | (y & 0xffffffffL);
    }

    /** The second dimension's 32 digits for index i, first digit in the lowest bit. */
    static int secondDimensionReversed(int index) {
        int bits = 0;
        for (int k = 0, i = index; i != 0; i >>>= 1, k++) {
            if ((i & 1) != 0) {
                bits ^= REVERSED_COLUMNS[k];
            }
        }
        return bits;
    }

    /**
     * Owen's nested uniform scrambling of a 32-digit fraction given with its first digit in the
     * lowest bit: a hash in which each bit changes only bits above it (multiplications carry
     * upwards), so each digit is flipped by a function of the seed and the digits before it.
     * Returns the scrambled fraction with its first digit in the highest bit.
     */
    static int owen(int reversed, int seed) {
        int v = reversed;
        v ^= v * 0x3d20adea;
        v += seed;
        v *= (seed >>> 16) | 1;
        v ^= v * 0x05526c56;
        v ^= v * 0x53a22864;
        return Integer.reverse(v);
    }

    /** The first n points, scrambled by two values of {@code rng}: one pattern per call. */
    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        long scramble = rng.nextLong();
        for (int i = 0; i < n; i++) {
            long p = point(i, scramble);
            xs[i] = (p >>> 32) * 0x1.0p-32;
            ys[i] = (p & 0xffffffffL) * 0x1.0p-32;
        }
    }
}

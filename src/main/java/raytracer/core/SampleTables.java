package raytracer.core;

import java.util.concurrent.ConcurrentHashMap;
import raytracer.math.Hashes;
import raytracer.math.Rng;

/**
 * The sample sets of one render, shared by its workers (Suffern, section 5.3: num_sets sets of
 * points and shuffled indices, made once): for each pattern size c asked for, a number of
 * patterns of c points from the render's sampler, and permutations of the pixel's samples, all
 * drawn from generators seeded by (seed, c, set), so they are the same whichever worker asks
 * first. A pixel's dimension picks one pattern and one permutation by hashing, so a sample costs
 * two table reads, not a pattern's generation.
 *
 * <p>The book's samplers' patterns are shuffled once as made, so that the points a sample takes
 * together are any of them; a pointwise sequence (Sobol') keeps its order, in which every aligned
 * block of 2^k points is itself stratified.
 */
public final class SampleTables {
    /** Points kept per pattern size, at most: the number of patterns is this over the size, 1 to {@link #MOST_SETS}. */
    static final int POINTS_PER_SIZE = 1 << 16;
    static final int MOST_SETS = 1024;

    private final Sampler sampler;
    private final int spp;
    private final long seed;
    private final int[] permutations;
    private final int permutationMask;
    private final ConcurrentHashMap<Integer, Patterns> patterns = new ConcurrentHashMap<>();

    /** Tables for a render of {@code spp} samples per pixel from {@code sampler}, seeded {@code seed}. */
    public SampleTables(Sampler sampler, int spp, long seed) {
        this.sampler = sampler;
        this.spp = spp;
        this.seed = seed;
        int count = sets(spp);
        permutationMask = count - 1;
        permutations = new int[count * spp];
        Rng rng = new Rng(0);
        for (int p = 0; p < count; p++) {
            rng.reseed(Hashes.mix(seed, -1 - p));
            // Fisher-Yates from the identity: every order of the samples equally likely
            for (int i = 0; i < spp; i++) {
                int j = rng.nextInt(i + 1);
                permutations[p * spp + i] = permutations[p * spp + j];
                permutations[p * spp + j] = i;
            }
        }
    }

    /** How many patterns of {@code size} points are kept: a power of two, fewer for larger patterns. */
    static int sets(int size) {
        int sets = Integer.highestOneBit(Math.max(1, POINTS_PER_SIZE / size));
        return Math.min(MOST_SETS, sets);
    }

    public Sampler sampler() {
        return sampler;
    }

    public int spp() {
        return spp;
    }

    public long seed() {
        return seed;
    }

    /** Where permutation {@code hash} puts sample {@code i}: a value in 0 .. spp-1. */
    int permuted(int hash, int i) {
        return permutations[(hash & permutationMask) * spp + i];
    }

    /** The patterns of {@code size} points, made on first use. */
    Patterns patterns(int size) {
        return patterns.computeIfAbsent(size, this::make);
    }

    private Patterns make(int size) {
        int sets = sets(size);
        int n = sampler.supportedCount(size);
        double[] xs = new double[sets * size];
        double[] ys = new double[sets * size];
        double[] x = new double[n];
        double[] y = new double[n];
        Rng rng = new Rng(0);
        boolean shuffle = !sampler.keepsOrder();
        for (int s = 0; s < sets; s++) {
            rng.reseed(Hashes.mix(Hashes.mix(seed, size), s));
            sampler.generate(n, rng, x, y);
            if (shuffle) {
                for (int i = n - 1; i > 0; i--) {
                    int j = rng.nextInt(i + 1);
                    double t = x[i];
                    x[i] = x[j];
                    x[j] = t;
                    t = y[i];
                    y[i] = y[j];
                    y[j] = t;
                }
            }
            // a sampler that cannot make `size` points (a fixed count) repeats its pattern
            for (int i = 0; i < size; i++) {
                xs[s * size + i] = x[i % n];
                ys[s * size + i] = y[i % n];
            }
        }
        return new Patterns(size, sets - 1, xs, ys);
    }

    /** {@code mask + 1} patterns of {@code size} points, one after another. */
    record Patterns(int size, int mask, double[] xs, double[] ys) {
    }
}

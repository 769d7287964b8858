package raytracer.core;

import java.util.Arrays;
import raytracer.math.Rng;

/**
 * The patterns one pixel has drawn so far, by dimension: each made whole by a book sampler the
 * first time the pixel asks for it, from a generator seeded by the dimension's key, then shuffled
 * (Suffern's shuffled indices, section 5.3), and kept until the next pixel. An open-addressing
 * table over a pool of buffers, both grown when a pixel needs more: after the first pixels a
 * worker allocates nothing.
 */
final class SampleSets {
    private final Sampler sampler;
    private final Rng rng = new Rng(0);

    private long[] keys = new long[64];
    private int[] counts = new int[64];
    private int[] entries = new int[64];
    /** A slot is in use when its stamp is the current pixel's. */
    private int[] stamps = new int[64];
    private int stamp = 1;

    private double[][] xs = new double[8][];
    private double[][] ys = new double[8][];
    private int[] sizes = new int[8];
    private int used;

    SampleSets(Sampler sampler) {
        this.sampler = sampler;
    }

    /** Forgets every pattern: the next pixel draws its own. */
    void clear() {
        used = 0;
        if (++stamp == Integer.MAX_VALUE) {
            Arrays.fill(stamps, 0);
            stamp = 1;
        }
    }

    /** The pattern of {@code count} points for dimension {@code key}, drawn if the pixel has not yet. */
    int find(long key, int count) {
        int mask = keys.length - 1;
        int slot = (int) key & mask;
        while (stamps[slot] == stamp) {
            if (keys[slot] == key && counts[slot] == count) {
                return entries[slot];
            }
            slot = (slot + 1) & mask;
        }
        if (2 * (used + 1) > keys.length) {
            grow();
            return find(key, count);
        }
        int entry = draw(key, count);
        keys[slot] = key;
        counts[slot] = count;
        entries[slot] = entry;
        stamps[slot] = stamp;
        return entry;
    }

    int size(int entry) {
        return sizes[entry];
    }

    double[] x(int entry) {
        return xs[entry];
    }

    double[] y(int entry) {
        return ys[entry];
    }

    private int draw(long key, int count) {
        if (used == xs.length) {
            xs = Arrays.copyOf(xs, 2 * used);
            ys = Arrays.copyOf(ys, 2 * used);
            sizes = Arrays.copyOf(sizes, 2 * used);
        }
        int n = sampler.supportedCount(count);
        if (xs[used] == null || xs[used].length < n) {
            xs[used] = new double[n];
            ys[used] = new double[n];
        }
        double[] x = xs[used];
        double[] y = ys[used];
        rng.reseed(key);
        sampler.generate(n, rng, x, y);
        // Fisher-Yates: every order equally likely, so sample i's point is any of the n
        for (int i = n - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            double t = x[i];
            x[i] = x[j];
            x[j] = t;
            t = y[i];
            y[i] = y[j];
            y[j] = t;
        }
        sizes[used] = n;
        return used++;
    }

    private void grow() {
        long[] oldKeys = keys;
        int[] oldCounts = counts;
        int[] oldEntries = entries;
        int[] oldStamps = stamps;
        int capacity = 2 * oldKeys.length;
        keys = new long[capacity];
        counts = new int[capacity];
        entries = new int[capacity];
        stamps = new int[capacity];
        for (int i = 0; i < oldKeys.length; i++) {
            if (oldStamps[i] == stamp) {
                int slot = (int) oldKeys[i] & (capacity - 1);
                while (stamps[slot] == stamp) {
                    slot = (slot + 1) & (capacity - 1);
                }
                keys[slot] = oldKeys[i];
                counts[slot] = oldCounts[i];
                entries[slot] = oldEntries[i];
                stamps[slot] = stamp;
            }
        }
    }
}

package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** Kensler's hashed permutation is a permutation of 0 .. n-1 for every n and seed, and a fair one. */
class HashesTest {

    @Test
    void permuteIsABijectionForEveryCountAndSeed() {
        for (int n = 1; n <= 300; n++) {
            for (int seed : new int[] {0, 1, -1, 0x12345678, 0x9e3779b9, n * 7919}) {
                boolean[] seen = new boolean[n];
                for (int i = 0; i < n; i++) {
                    int p = Hashes.permute(i, n, seed);
                    assertTrue(p >= 0 && p < n && !seen[p], "n " + n + ", seed " + seed + ": " + i + " -> " + p);
                    seen[p] = true;
                }
            }
        }
    }

    @Test
    void everyElementGoesAnywhereEquallyOften() {
        // where element 3 of 16 lands, over 16,000 seeds made by hashing: each of 16 places about
        // 1,000 times (a permutation that kept element 3 near 3 would fail)
        int[] counts = new int[16];
        for (int s = 0; s < 16000; s++) {
            counts[Hashes.permute(3, 16, (int) Hashes.mix(s))]++;
        }
        double chi2 = Arrays.stream(counts).mapToDouble(c -> (c - 1000.0) * (c - 1000.0) / 1000).sum();
        assertTrue(chi2 < 15 + 4.5 * Math.sqrt(30) + 8, "chi-square " + chi2 + ": " + Arrays.toString(counts));
    }
}

package raytracer.samplers;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.core.Sampler;
import raytracer.math.Hashes;
import raytracer.math.Rng;

class SamplerPropertiesTest {

    private static double[][] draw(Sampler s, int n, long seed) {
        double[] xs = new double[n];
        double[] ys = new double[n];
        s.generate(n, new Rng(seed), xs, ys);
        return new double[][] {xs, ys};
    }

    /** Counts points per cell of a cols x rows grid. */
    private static int[] histogram(double[] xs, double[] ys, int cols, int rows) {
        int[] counts = new int[cols * rows];
        for (int i = 0; i < xs.length; i++) {
            counts[(int) (ys[i] * rows) * cols + (int) (xs[i] * cols)]++;
        }
        return counts;
    }

    @ParameterizedTest
    @ValueSource(strings = {"jittered", "multi-jittered", "correlated-multi-jittered", "regular"})
    void oneSamplePerStratum(String name) {
        Sampler s = Samplers.byName(name);
        for (int k : new int[] {1, 2, 4, 8}) {
            for (long seed = 0; seed < 20; seed++) {
                double[][] p = draw(s, k * k, seed);
                int[] cells = histogram(p[0], p[1], k, k);
                assertTrue(Arrays.stream(cells).allMatch(c -> c == 1), name + " k=" + k + " " + Arrays.toString(cells));
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"n-rooks", "multi-jittered", "correlated-multi-jittered"})
    void oneSamplePerRowAndColumnOfTheFineGrid(String name) {
        Sampler s = Samplers.byName(name);
        for (int n : new int[] {1, 4, 9, 16, 64}) {
            for (long seed = 0; seed < 20; seed++) {
                double[][] p = draw(s, n, seed);
                assertTrue(Arrays.stream(histogram(p[0], p[1], n, 1)).allMatch(c -> c == 1), name + " columns, n=" + n);
                assertTrue(Arrays.stream(histogram(p[0], p[1], 1, n)).allMatch(c -> c == 1), name + " rows, n=" + n);
            }
        }
    }

    @Test
    void nRooksIsNotJustTheDiagonal() {
        double[][] p = draw(new NRooks(), 16, 3);
        int offDiagonal = 0;
        for (int i = 0; i < 16; i++) {
            if ((int) (p[0][i] * 16) != (int) (p[1][i] * 16)) {
                offDiagonal++;
            }
        }
        assertTrue(offDiagonal > 8, "the columns should be shuffled: " + offDiagonal);
    }

    @Test
    void hammersleyHasKnownRadicalInversesAndOnePointPerColumn() {
        double[][] p = draw(new Hammersley(), 8, 0);
        assertArrayEquals(new double[] {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875}, p[1], 0);
        assertTrue(Arrays.stream(histogram(p[0], p[1], 8, 1)).allMatch(c -> c == 1));
        assertTrue(Arrays.stream(histogram(p[0], p[1], 1, 8)).allMatch(c -> c == 1));
    }

    @ParameterizedTest
    @ValueSource(strings = {"regular", "random", "jittered", "n-rooks", "multi-jittered", "correlated-multi-jittered", "hammersley",
                            "sobol"})
    void pointsStayInTheUnitSquare(String name) {
        Sampler s = Samplers.byName(name);
        for (int n : new int[] {1, 2, 9, 64, 100}) {
            for (long seed = 0; seed < 50; seed++) {
                double[][] p = draw(s, s.supportedCount(n), seed);
                for (int i = 0; i < p[0].length; i++) {
                    assertTrue(p[0][i] >= 0 && p[0][i] < 1 && p[1][i] >= 0 && p[1][i] < 1, name + " " + p[0][i] + ", " + p[1][i]);
                }
            }
        }
    }

    @Test
    void regularAndHammersleyPointsAreExact() {
        double[][] regular = draw(new Regular(), 9, 0);
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                assertEquals((col + 0.5) / 3, regular[0][row * 3 + col], 0);
                assertEquals((row + 0.5) / 3, regular[1][row * 3 + col], 0);
            }
        }
        double[][] hammersley = draw(new Hammersley(), 8, 0);
        assertArrayEquals(new double[] {0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875}, hammersley[0], 0);
        // base-2 radical inverse of 1..7: mirror the binary digits about the point
        assertArrayEquals(new double[] {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875}, hammersley[1], 0);
        assertEquals(0b1011 / 16.0, draw(new Hammersley(), 14, 0)[1][13], 0, "13 = 1101b -> 0.1011b");
    }

    /**
     * Pearson's chi-square of counts against equal expectations; for d degrees of freedom it
     * exceeds d + 4.5 sqrt(2 d) + 8 with probability below about 1e-4 (Wilson-Hilferty), so with
     * the fixed seeds here only a sampler that is not uniform fails.
     */
    private static void assertUniform(int[] counts, String what) {
        double total = Arrays.stream(counts).sum();
        double expected = total / counts.length;
        double chi2 = Arrays.stream(counts).mapToDouble(c -> (c - expected) * (c - expected) / expected).sum();
        int dof = counts.length - 1;
        assertTrue(chi2 < dof + 4.5 * Math.sqrt(2 * dof) + 8, what + ": chi-square " + chi2 + " for " + Arrays.toString(counts));
    }

    /** Where inside its stratum of width 1/strata each coordinate lies, in 10 bins, over many seeds. */
    private static int[] offsetsInStrata(Sampler s, int n, int strata, int axis) {
        int[] bins = new int[10];
        for (long seed = 0; seed < 400; seed++) {
            for (double v : draw(s, n, seed)[axis]) {
                double offset = v * strata - Math.floor(v * strata);
                bins[(int) (offset * 10)]++;
            }
        }
        return bins;
    }

    @Test
    void pointsAreUniformWithinTheirStrata() {
        // a pattern that is stratified but always at the stratum's centre (or corner) fails here
        for (int axis = 0; axis < 2; axis++) {
            String xy = axis == 0 ? " x" : " y";
            assertUniform(offsetsInStrata(new Jittered(), 16, 4, axis), "jittered in its 4 x 4 cells" + xy);
            assertUniform(offsetsInStrata(new MultiJittered(), 16, 16, axis), "multi-jittered in its 16 sub-columns" + xy);
            assertUniform(offsetsInStrata(new CorrelatedMultiJittered(), 16, 16, axis),
                          "correlated multi-jittered in its 16 sub-columns" + xy);
            assertUniform(offsetsInStrata(new NRooks(), 16, 16, axis), "n-rooks in its 16 columns" + xy);
            assertUniform(offsetsInStrata(new PureRandom(), 16, 1, axis), "random" + xy);
        }
        // and random's x and y are independent: equal counts in the cells of a 4 x 4 grid
        int[] cells = new int[16];
        for (long seed = 0; seed < 400; seed++) {
            double[][] p = draw(new PureRandom(), 16, seed);
            int[] h = histogram(p[0], p[1], 4, 4);
            for (int c = 0; c < 16; c++) {
                cells[c] += h[c];
            }
        }
        assertUniform(cells, "random over a 4 x 4 grid");
    }

    @Test
    void shufflesReachEveryArrangement() {
        // n-rooks: the column of the point in row 0 is any of the n; multi-jittered: the point of cell
        // (0, 0) lies in any of its k sub-columns. A biased shuffle (Sattolo's, or none) fails.
        int[] column = new int[4];
        int[] subColumn = new int[4];
        for (long seed = 0; seed < 4000; seed++) {
            double[][] rooks = draw(new NRooks(), 4, seed);
            for (int i = 0; i < 4; i++) {
                if ((int) (rooks[1][i] * 4) == 0) {
                    column[(int) (rooks[0][i] * 4)]++;
                }
            }
            double[][] mj = draw(new MultiJittered(), 16, seed);
            for (int i = 0; i < 16; i++) {
                if ((int) (mj[0][i] * 4) == 0 && (int) (mj[1][i] * 4) == 0) {
                    subColumn[(int) (mj[0][i] * 16)]++;
                }
            }
        }
        assertUniform(column, "n-rooks: column of row 0");
        assertUniform(subColumn, "multi-jittered: sub-column in cell (0, 0)");
        int[] correlated = new int[4];
        for (long seed = 0; seed < 4000; seed++) {
            double[][] cmj = draw(new CorrelatedMultiJittered(), 16, seed);
            for (int i = 0; i < 16; i++) {
                if ((int) (cmj[0][i] * 4) == 0 && (int) (cmj[1][i] * 4) == 0) {
                    correlated[(int) (cmj[0][i] * 16)]++;
                }
            }
        }
        assertUniform(correlated, "correlated multi-jittered: sub-column in cell (0, 0)");
    }

    @Test
    void correlatedMultiJitteredSharesOneShuffleAmongTheCellColumns() {
        // the sub-column of the point in cell row j is sigma(j) in every cell column (and the
        // sub-row of the point in cell column i is tau(i) in every cell row): Kensler's correlation.
        // Chiu et al.'s multi-jittered shuffles each cell column on its own, so it differs somewhere.
        int k = 5;
        boolean independentDiffer = false;
        for (long seed = 0; seed < 50; seed++) {
            double[][] cmj = draw(new CorrelatedMultiJittered(), k * k, seed);
            int[][] sub = subStrata(cmj, k);
            for (int j = 0; j < k; j++) {
                for (int i = 1; i < k; i++) {
                    assertEquals(sub[0][j * k], sub[0][j * k + i], "seed " + seed + ": sub-column of row " + j + ", column " + i);
                    assertEquals(sub[1][i], sub[1][j * k + i], "seed " + seed + ": sub-row of column " + i + ", row " + j);
                }
            }
            int[][] mj = subStrata(draw(new MultiJittered(), k * k, seed), k);
            for (int j = 0; j < k; j++) {
                for (int i = 1; i < k; i++) {
                    independentDiffer |= mj[0][j * k] != mj[0][j * k + i];
                }
            }
        }
        assertTrue(independentDiffer, "the test tells the two apart");
    }

    /** Per cell (row j, column i at j k + i): the point's sub-column and sub-row within its cell. */
    private static int[][] subStrata(double[][] p, int k) {
        int[][] sub = new int[2][k * k];
        for (int q = 0; q < k * k; q++) {
            int column = (int) (p[0][q] * k);
            int row = (int) (p[1][q] * k);
            sub[0][row * k + column] = (int) (p[0][q] * k * k) - column * k;
            sub[1][row * k + column] = (int) (p[1][q] * k * k) - row * k;
        }
        return sub;
    }

    @ParameterizedTest
    @ValueSource(strings = {"random", "jittered", "n-rooks", "multi-jittered", "correlated-multi-jittered", "sobol"})
    void sameSeedSamePointsOtherSeedOtherPoints(String name) {
        Sampler s = Samplers.byName(name);
        int n = s.supportedCount(16);
        assertArrayEquals(draw(s, n, 7)[0], draw(s, n, 7)[0]);
        assertFalse(Arrays.equals(draw(s, n, 7)[0], draw(s, n, 8)[0]));
    }

    /** Binomial coefficient c choose r, mod 2, by Pascal's rule: an entry of Sobol's second generator matrix. */
    private static int pascalMod2(int r, int c) {
        int[] row = {1};
        for (int k = 1; k <= c; k++) {
            int[] next = new int[k + 1];
            next[0] = 1;
            next[k] = 1;
            for (int j = 1; j < k; j++) {
                next[j] = (row[j - 1] + row[j]) % 2;
            }
            row = next;
        }
        return r <= c ? row[r] : 0;
    }

    @Test
    void sobolsSecondDimensionIsThePascalMatrixMod2() {
        // digit r + 1 of y(i) is the sum mod 2 over the bits c of i of (c choose r) (Sobol's second
        // dimension; its direction numbers are all 1): computed here from the binomials
        for (int i = 0; i < 1024; i++) {
            int expected = 0;
            for (int r = 0; r < 31; r++) {
                int digit = 0;
                for (int c = 0; c < 11; c++) {
                    digit ^= (i >>> c & 1) * pascalMod2(r, c);
                }
                expected |= digit << r;
            }
            assertEquals(expected, Sobol.secondDimensionReversed(i), "y(" + i + ")");
        }
        // the first 8 values of y, digits read the usual way: 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8
        double[] y = new double[8];
        for (int i = 0; i < 8; i++) {
            y[i] = (Integer.reverse(Sobol.secondDimensionReversed(i)) & 0xffffffffL) * 0x1.0p-32;
        }
        assertArrayEquals(new double[] {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875}, y, 0);
    }

    @Test
    void scrambledSobolIsA02SequenceInEveryBlock() {
        // every aligned block of 2^m points puts one point in each elementary box of area 2^-m,
        // 2^a x 2^(m-a) cells, for every a: the (0,2)-sequence property, which Owen's scrambling keeps
        Sobol sobol = new Sobol();
        double[] xs = new double[256];
        double[] ys = new double[256];
        for (long seed = 0; seed < 30; seed++) {
            sobol.generate(256, new Rng(seed), xs, ys);
            for (int m = 0; m <= 8; m++) {
                int size = 1 << m;
                for (int from = 0; from < 256; from += size) {
                    for (int a = 0; a <= m; a++) {
                        int cols = 1 << a;
                        int rows = size / cols;
                        int[] cells = new int[size];
                        for (int i = from; i < from + size; i++) {
                            cells[(int) (ys[i] * rows) * cols + (int) (xs[i] * cols)]++;
                        }
                        assertTrue(Arrays.stream(cells).allMatch(c -> c == 1),
                                   "seed " + seed + ", points " + from + ".." + (from + size - 1) + ", " + cols + " x " + rows);
                    }
                }
            }
        }
    }

    @Test
    void owenScramblingMakesEachPointUniform() {
        // point 5 of the sequence over 6,400 scrambles, in 8 x 8 cells; and inside its stratum of 1/8
        // (a scramble that flipped only the leading digits would leave the finer ones fixed)
        Sobol sobol = new Sobol();
        int[] cells = new int[64];
        int[] fine = new int[10];
        for (int s = 0; s < 6400; s++) {
            long p = Sobol.point(5, Hashes.mix(s));
            double x = (p >>> 32) * 0x1.0p-32;
            double y = (p & 0xffffffffL) * 0x1.0p-32;
            cells[(int) (y * 8) * 8 + (int) (x * 8)]++;
            fine[(int) ((x * 8 - Math.floor(x * 8)) * 10)]++;
        }
        assertUniform(cells, "point 5 over scrambles");
        assertUniform(fine, "point 5 within its column of 1/8");
    }

    @Test
    void squarePatternsRoundTheCountUpToASquare() {
        assertEquals(1, new Jittered().supportedCount(1));
        assertEquals(4, new Jittered().supportedCount(2));
        assertEquals(16, new MultiJittered().supportedCount(16));
        assertEquals(25, new Regular().supportedCount(17));
        assertEquals(17, new NRooks().supportedCount(17));
        assertEquals(17, new Hammersley().supportedCount(17));
    }

    @Test
    void unknownNameListsTheAllowedOnes() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Samplers.byName("poisson-disk"));
        assertTrue(e.getMessage().contains("poisson-disk") && e.getMessage().contains("multi-jittered"), e.getMessage());
    }
}

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
    @ValueSource(strings = {"jittered", "multi-jittered", "regular"})
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
    @ValueSource(strings = {"n-rooks", "multi-jittered"})
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
    @ValueSource(strings = {"regular", "random", "jittered", "n-rooks", "multi-jittered", "hammersley"})
    void pointsStayInTheUnitSquareAndAverageOneHalf(String name) {
        Sampler s = Samplers.byName(name);
        int n = s.supportedCount(64);
        double sumX = 0;
        double sumY = 0;
        int total = 0;
        for (long seed = 0; seed < 200; seed++) {
            double[][] p = draw(s, n, seed);
            for (int i = 0; i < n; i++) {
                assertTrue(p[0][i] >= 0 && p[0][i] < 1 && p[1][i] >= 0 && p[1][i] < 1, name);
                sumX += p[0][i];
                sumY += p[1][i];
                total++;
            }
        }
        assertEquals(0.5, sumX / total, 0.01, name);
        assertEquals(0.5, sumY / total, 0.01, name);
    }

    @ParameterizedTest
    @ValueSource(strings = {"random", "jittered", "n-rooks", "multi-jittered"})
    void sameSeedSamePointsOtherSeedOtherPoints(String name) {
        Sampler s = Samplers.byName(name);
        int n = s.supportedCount(16);
        assertArrayEquals(draw(s, n, 7)[0], draw(s, n, 7)[0]);
        assertFalse(Arrays.equals(draw(s, n, 7)[0], draw(s, n, 8)[0]));
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
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Samplers.byName("sobol"));
        assertTrue(e.getMessage().contains("sobol") && e.getMessage().contains("multi-jittered"), e.getMessage());
    }
}

package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.samplers.Samplers;

/**
 * The properties the renderer relies on: a value depends on (seed, pixel, sample index, dimension)
 * alone; in each dimension the pixel's samples form one stratified pattern; dimensions are not
 * copies of each other; every value, taken over pixels, is uniform (so estimates stay unbiased).
 */
class PixelSamplesTest {
    private static final int LEVELS = 4;

    /** A worker's samples for a render of 16 spp from the sampler {@code name}, seeded 7. */
    private static Worker worker(String name) {
        return new Worker(new SampleTables(Samplers.byName(name), 16, 7), new PixelSamples(LEVELS));
    }

    private record Worker(SampleTables tables, PixelSamples p) {
        void startPixel(int x, int y) {
            p.startPixel(tables, x, y);
        }
    }

    /** The 2D value of sample i of pixel (x, y) in light 0's dimension at depth 0, m values per hit. */
    private static double[] light(Worker w, int x, int y, int i, int s, int m) {
        w.startPixel(x, y);
        PixelSamples p = w.p();
        p.startSample(i);
        p.get2D(0, PixelSamples.LIGHT, s, m);
        return new double[] {p.u, p.v};
    }

    /** The spp * m values of one dimension of one pixel, sample by sample. */
    private static double[][] pattern(Worker w, int x, int y, int purpose, int spp, int m) {
        double[][] points = new double[spp * m][];
        w.startPixel(x, y);
        PixelSamples p = w.p();
        for (int i = 0; i < spp; i++) {
            p.startSample(i);
            for (int s = 0; s < m; s++) {
                p.get2D(0, purpose, s, m);
                points[i * m + s] = new double[] {p.u, p.v};
            }
        }
        return points;
    }

    /** Whether every cell of a cols x rows grid over the unit square holds exactly one of the points. */
    private static boolean onePerCell(double[][] points, int from, int count, int cols, int rows) {
        int[] cells = new int[cols * rows];
        for (int i = from; i < from + count; i++) {
            cells[(int) (points[i][1] * rows) * cols + (int) (points[i][0] * cols)]++;
        }
        return Arrays.stream(cells).allMatch(c -> c == 1);
    }

    /** Pearson's chi-square against equal expectations, below the bound the samplers' tests use (p about 1e-4). */
    private static void assertUniform(int[] counts, String what) {
        double total = Arrays.stream(counts).sum();
        double expected = total / counts.length;
        double chi2 = Arrays.stream(counts).mapToDouble(c -> (c - expected) * (c - expected) / expected).sum();
        int dof = counts.length - 1;
        assertTrue(chi2 < dof + 4.5 * Math.sqrt(2 * dof) + 8, what + ": chi-square " + chi2 + " for " + dof + " degrees of freedom");
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "sobol", "random", "n-rooks"})
    void aValueDoesNotDependOnWhatWasDrawnBefore(String name) {
        SampleTables tables = new SampleTables(Samplers.byName(name), 16, 7);
        PixelSamples fresh = new PixelSamples(LEVELS);
        PixelSamples used = new PixelSamples(LEVELS);
        for (int x = 0; x < 20; x++) {
            // the other worker has drawn other pixels, other samples of this one, other dimensions
            // and deeper paths, in another order
            used.startPixel(tables, x + 1, 4);
            used.startSample(3);
            used.get2D(0, PixelSamples.LIGHT, 0, 1);
            used.startPixel(tables, x, 5);
            for (int i = 15; i >= 0; i--) {
                used.startSample(i);
                used.get2D(0, PixelSamples.PIXEL, 0, 1);
                used.branch(0, PixelSamples.GLOSSY_RAY, i % 4, 4);
                used.get2D(1, PixelSamples.LIGHT + 1, 0, 16);
                used.inherit(1);
                used.get2D(2, PixelSamples.GLOSSY, 1, 4);
            }
            for (int i = 0; i < 16; i++) {
                used.startSample(i);
                used.get2D(0, PixelSamples.LIGHT, 0, 1);
                fresh.startPixel(new SampleTables(Samplers.byName(name), 16, 7), x, 5);
                fresh.startSample(i);
                fresh.get2D(0, PixelSamples.LIGHT, 0, 1);
                assertEquals(fresh.u, used.u, 0, name + ": pixel " + x + ", sample " + i);
                assertEquals(fresh.v, used.v, 0, name + ": pixel " + x + ", sample " + i);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "jittered", "sobol"})
    void aPixelsSamplesFormOneStratifiedPatternPerDimension(String name) {
        Worker w = worker(name);
        PixelSamples p = w.p();
        for (int x = 0; x < 50; x++) {
            for (int purpose : new int[] {PixelSamples.PIXEL, PixelSamples.LENS, PixelSamples.LIGHT, PixelSamples.LIGHT + 2}) {
                double[][] one = pattern(w, x, 1, purpose, 16, 1);
                assertTrue(onePerCell(one, 0, 16, 4, 4), name + ": 16 samples with one value each, 4 x 4 cells, pixel " + x);
                // 16 samples taking 4 values each: one pattern of 64 points
                double[][] four = pattern(w, x, 1, purpose, 16, 4);
                assertTrue(onePerCell(four, 0, 64, 8, 8), name + ": 16 x 4 values, 8 x 8 cells, pixel " + x);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "sobol"})
    void theStrataAreFineInBothDirections(String name) {
        // multi-jittered: one point per column and row of the 16 x 16 grid too; Sobol': every
        // elementary box of area 1/16 (16 x 1, 8 x 2, 4 x 4, 2 x 8, 1 x 16)
        Worker w = worker(name);
        PixelSamples p = w.p();
        for (int x = 0; x < 50; x++) {
            double[][] points = pattern(w, x, 2, PixelSamples.LIGHT, 16, 1);
            assertTrue(onePerCell(points, 0, 16, 16, 1) && onePerCell(points, 0, 16, 1, 16), name + ", pixel " + x);
            if (name.equals("sobol")) {
                assertTrue(onePerCell(points, 0, 16, 8, 2) && onePerCell(points, 0, 16, 2, 8), "sobol, pixel " + x);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 4, 16})
    void eachSampleOfSobolTakesAStratifiedBlock(int m) {
        // the m light samples of one hit: an aligned block of a (0,2)-sequence, one point in each
        // square of side 1/sqrt(m)
        Worker w = worker("sobol");
        int side = (int) Math.round(Math.sqrt(m));
        for (int x = 0; x < 20; x++) {
            double[][] points = pattern(w, x, 0, PixelSamples.LIGHT, 16, m);
            for (int i = 0; i < 16; i++) {
                assertTrue(onePerCell(points, i * m, m, side, side), "sample " + i + " of pixel " + x);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "sobol", "jittered"})
    void dimensionsAreNotCopiesOfEachOther(String name) {
        // the pairs (pixel position of sample i, its light sample): in which of 4 x 4 cells each
        // lies. Copies of one pattern would pair cell c with cell c every time; independent
        // shuffles spread the pairs over all 256 pairs of cells
        Worker w = worker(name);
        PixelSamples p = w.p();
        int[] pixelWithLight = new int[256];
        int[] lightWithLight = new int[256];
        int[] depth0WithDepth1 = new int[256];
        for (int x = 0; x < 400; x++) {
            double[][] position = pattern(w, x, 0, PixelSamples.PIXEL, 16, 1);
            double[][] light0 = pattern(w, x, 0, PixelSamples.LIGHT, 16, 1);
            double[][] light1 = pattern(w, x, 0, PixelSamples.LIGHT + 1, 16, 1);
            for (int i = 0; i < 16; i++) {
                p.startSample(i);
                p.branch(0, PixelSamples.REFLECTED, 0, 1);
                p.get2D(1, PixelSamples.LIGHT, 0, 1);
                pixelWithLight[cell(position[i]) * 16 + cell(light0[i])]++;
                lightWithLight[cell(light0[i]) * 16 + cell(light1[i])]++;
                depth0WithDepth1[cell(light0[i]) * 16 + cell(new double[] {p.u, p.v})]++;
            }
        }
        assertUniform(pixelWithLight, name + ": pixel position and light 0");
        assertUniform(lightWithLight, name + ": light 0 and light 1");
        assertUniform(depth0WithDepth1, name + ": light 0 at the camera ray's hit and at the mirror ray's");
    }

    private static int cell(double[] point) {
        return (int) (point[1] * 4) * 4 + (int) (point[0] * 4);
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "sobol", "random"})
    void everyValueIsUniformOverPixels(String name) {
        // sample 5's light value over 4000 pixels, in 8 x 8 cells: a shuffle or scramble that
        // favoured some points of a pattern would bias the estimates
        Worker w = worker(name);
        PixelSamples p = w.p();
        int[] cells = new int[64];
        for (int x = 0; x < 4000; x++) {
            double[] v = light(w, x, 9, 5, 0, 1);
            cells[(int) (v[1] * 8) * 8 + (int) (v[0] * 8)]++;
        }
        assertUniform(cells, name);
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "sobol"})
    void branchesHaveTheirOwnDimensionsAndGlossyRaysShareOnePattern(String name) {
        Worker w = worker(name);
        PixelSamples p = w.p();
        w.startPixel(2, 3);
        p.startSample(0);
        p.branch(0, PixelSamples.REFLECTED, 0, 1);
        p.get2D(1, PixelSamples.LIGHT, 0, 1);
        double reflected = p.u;
        p.branch(0, PixelSamples.REFRACTED, 0, 1);
        p.get2D(1, PixelSamples.LIGHT, 0, 1);
        assertNotEquals(reflected, p.u, "the refracted ray's hit samples the light apart from the reflected one's");
        // 16 samples, 4 glossy rays each: the light samples at the 64 rays' hits form one pattern
        double[][] points = new double[64][];
        for (int i = 0; i < 16; i++) {
            p.startSample(i);
            for (int j = 0; j < 4; j++) {
                p.branch(0, PixelSamples.GLOSSY_RAY, j, 4);
                p.get2D(1, PixelSamples.LIGHT, 0, 1);
                points[i * 4 + j] = new double[] {p.u, p.v};
            }
        }
        assertTrue(onePerCell(points, 0, 64, 8, 8), name + ": light samples under 16 x 4 glossy rays");
    }

    @ParameterizedTest
    @ValueSource(strings = {"multi-jittered", "sobol"})
    void theSeedAndThePixelChangeTheValues(String name) {
        Worker w = worker(name);
        PixelSamples p = w.p();
        double[] a = light(w, 0, 0, 0, 0, 1);
        double[] b = light(w, 1, 0, 0, 0, 1);
        assertNotEquals(a[0], b[0]);
        p.startPixel(new SampleTables(Samplers.byName(name), 16, 8), 0, 0);
        p.startSample(0);
        p.get2D(0, PixelSamples.LIGHT, 0, 1);
        assertNotEquals(a[0], p.u);
    }
}

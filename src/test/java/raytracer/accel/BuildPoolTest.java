package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.SplittableRandom;
import java.util.concurrent.ForkJoinPool;
import java.util.function.ToIntFunction;
import org.junit.jupiter.api.Test;

/**
 * A median or SAH build started on a pool's worker forks its subtrees into that pool, so that the command
 * line's one pool, sized by --threads, does the build (it used the common pool whatever the pool of
 * the caller).
 */
class BuildPoolTest {
    /** {@code n} boxes of side up to 0.01 in the unit cube, as floats rounded outward would be. */
    private static float[] boxes(int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        float[] boxes = new float[6 * n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                float lo = (float) random.nextDouble();
                boxes[6 * i + k] = lo;
                boxes[6 * i + 3 + k] = lo + (float) random.nextDouble(0.01);
            }
        }
        return boxes;
    }

    @Test
    void aParallelMedianBuildOnAPoolOfOneRunsOnItsOneThread() throws Exception {
        MedianSplitBuilder serial = new MedianSplitBuilder(4, Integer.MAX_VALUE);
        MedianSplitBuilder parallel = new MedianSplitBuilder(4, 1000);
        assertRunsOnAPoolOfOne(boxes -> serial.build(boxes).nodeCount(), boxes -> parallel.build(boxes).nodeCount());
    }

    @Test
    void aParallelSahBuildOnAPoolOfOneRunsOnItsOneThread() throws Exception {
        SahBuilder serial = new SahBuilder(4, Integer.MAX_VALUE);
        SahBuilder parallel = new SahBuilder(4, 1000);
        assertRunsOnAPoolOfOne(boxes -> serial.build(boxes).nodeCount(), boxes -> parallel.build(boxes).nodeCount());
    }

    private static void assertRunsOnAPoolOfOne(ToIntFunction<float[]> serial, ToIntFunction<float[]> parallel) throws Exception {
        // on a pool of one thread, the caller's thread spends the whole build's CPU time when the
        // subtrees fork into its own pool, and almost none when they run elsewhere while it waits
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        assertTrue(threads.isCurrentThreadCpuTimeSupported());
        float[] boxes = boxes(100_000, 11);
        ForkJoinPool one = new ForkJoinPool(1);
        try {
            long[] cpu = one.submit(() -> {
                long[] spent = new long[2];
                for (int round = 0; round < 2; round++) { // the first round compiles the builder
                    long start = threads.getCurrentThreadCpuTime();
                    int serialNodes = serial.applyAsInt(boxes.clone());
                    long between = threads.getCurrentThreadCpuTime();
                    int parallelNodes = parallel.applyAsInt(boxes.clone());
                    spent[0] = between - start;
                    spent[1] = threads.getCurrentThreadCpuTime() - between;
                    assertEquals(serialNodes, parallelNodes);
                }
                return spent;
            }).get();
            assertTrue(cpu[1] > cpu[0] / 3, "the caller's thread spent " + cpu[1] / 1e6 + " ms CPU on the parallel build, "
                                            + cpu[0] / 1e6 + " ms on the serial one");
            assertEquals(1, one.getPoolSize(), "no thread was added to the pool");
        } finally {
            one.shutdown();
        }
    }
}

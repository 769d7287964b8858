package raytracer.shapes.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The growing arrays of the loaders hold what was added, across the first block's doubling and further blocks. */
class GrowingTest {
    @Test
    void valuesComeBackInOrderAcrossBlocks() {
        Random random = new Random(7);
        int n = 2 * Growing.FOURS + 12_345; // three blocks of ints and floats, five of doubles
        Growing.Doubles d = new Growing.Doubles();
        Growing.Floats f = new Growing.Floats();
        Growing.Ints i = new Growing.Ints();
        double[] expectD = new double[n];
        float[] expectF = new float[n];
        int[] expectI = new int[n];
        int at = 0;
        while (at < n) {
            int run = Math.min(n - at, random.nextInt(3) == 0 ? 1 + random.nextInt(300_000) : 1);
            double[] values = new double[run];
            int[] ints = new int[run];
            for (int k = 0; k < run; k++) {
                values[k] = random.nextDouble();
                ints[k] = random.nextInt();
                expectD[at + k] = values[k];
                expectF[at + k] = (float) values[k];
                expectI[at + k] = ints[k];
                f.add((float) values[k]);
            }
            if (run == 1) {
                d.add(values[0]);
                i.add(ints[0]);
            } else {
                d.addAll(values, run);
                i.addAll(ints, run);
            }
            at += run;
        }
        assertEquals(n, d.size());
        for (int k = 0; k < n; k += 997) {
            assertEquals(expectD[k], d.get(k));
            assertEquals(expectF[k], f.get(k));
            assertEquals(expectI[k], i.get(k));
        }
        i.set(Growing.FOURS + 1, -5);
        expectI[Growing.FOURS + 1] = -5;
        i.fill(3, 10);
        int[] withFill = java.util.Arrays.copyOf(expectI, n + 10);
        java.util.Arrays.fill(withFill, n, n + 10, 3);
        assertArrayEquals(expectD, d.toArray());
        assertArrayEquals(expectF, f.toArray());
        assertArrayEquals(withFill, i.toArray());
        assertEquals(0, d.size(), "emptied by toArray");
        assertEquals(0, d.toArray().length);
    }
}

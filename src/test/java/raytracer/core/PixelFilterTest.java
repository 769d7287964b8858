package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The book's box filter: weight 1 inside a pixel's half width, nothing beyond, and no reach. */
class PixelFilterTest {
    @Test
    void theBoxWeighsOneInsideItsHalfPixelAndNothingBeyond() {
        for (double d : new double[] {0, 0.1, 0.25, 0.4999, -0.4999}) {
            assertEquals(1, PixelFilter.BOX.weight(d), "d = " + d);
        }
        for (double d : new double[] {0.5, 0.75, -2}) {
            assertEquals(0, PixelFilter.BOX.weight(d), "d = " + d);
        }
    }

    @Test
    void theBoxReachesNoOtherPixel() {
        assertEquals(0, PixelFilter.BOX.reach());
        assertTrue(PixelFilter.BOX.isBox());
        assertEquals("box", PixelFilter.BOX.name());
    }
}

package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The metrics against values worked out by hand on images of two and six pixels. */
class ErrorMetricsTest {

    /** Image pixels (1, 2, 3) and (0, 0, 0) against reference pixels (1, 1, 1) and (0.5, 0, 1). */
    private static Film[] twoPixels() {
        Film image = new Film(2, 1);
        image.set(0, 0, 1, 2, 3);
        image.set(1, 0, 0, 0, 0);
        Film reference = new Film(2, 1);
        reference.set(0, 0, 1, 1, 1);
        reference.set(1, 0, 0.5, 0, 1);
        return new Film[] {image, reference};
    }

    @Test
    void rmseRelativeRmseAndRelativeMseByHand() {
        Film[] f = twoPixels();
        ErrorMetrics m = ErrorMetrics.compare(f[0], 1, f[1]);
        // differences 0, 1, 2, -0.5, 0, -1: squares sum to 6.25 over n = 6 values
        assertEquals(Math.sqrt(6.25 / 6), m.rmse(), 1e-15);
        // reference mean (1 + 1 + 1 + 0.5 + 0 + 1) / 6 = 0.75
        assertEquals(0.75, m.referenceMean(), 1e-15);
        assertEquals(Math.sqrt(6.25 / 6) / 0.75, m.relativeRmse(), 1e-15);
        // (0 + 1 + 4) / (1 + 0.01) + 0.25 / (0.25 + 0.01) + 0 / 0.01 + 1 / (1 + 0.01), over 6
        assertEquals((5 / 1.01 + 0.25 / 0.26 + 1 / 1.01) / 6, m.relativeMse(), 1e-15);
        assertEquals(2, m.worst(), 0);
        assertEquals(0, m.worstX());
        assertEquals(0, m.worstY());
    }

    @Test
    void theDisplayedValuesAreClampedAndSrgbEncodedByHand() {
        Film[] f = twoPixels();
        ErrorMetrics m = ErrorMetrics.compareDisplayed(f[0], 1, f[1]);
        // clamped to [0, 1]: image (1, 1, 1), (0, 0, 0) against reference (1, 1, 1), (0.5, 0, 1); encoded,
        // 1 -> 1, 0 -> 0, 0.5 -> 1.055 * 0.5^(1/2.4) - 0.055 = 0.735356...: differences 0, 0, 0, -e, 0, -1
        double e = 1.055 * Math.pow(0.5, 1 / 2.4) - 0.055;
        assertEquals(0.7353569830524495, e, 1e-15);
        assertEquals(Math.sqrt((e * e + 1) / 6), m.rmse(), 1e-15);
        assertEquals((4 + e) / 6, m.referenceMean(), 1e-15);
        assertEquals(1, m.worst(), 1e-15, "1.055 - 0.055 is 1 to within an ulp");
        assertEquals(1, m.worstX(), "the black pixel where the reference is 1");
    }

    @Test
    void theImageIsScaledBeforeComparing() {
        Film[] f = twoPixels();
        ErrorMetrics m = ErrorMetrics.compare(f[0], 2, f[1]);
        // image (2, 4, 6), (0, 0, 0): differences 1, 3, 5, -0.5, 0, -1
        assertEquals(Math.sqrt((1 + 9 + 25 + 0.25 + 0 + 1) / 6.0), m.rmse(), 1e-15);
        assertEquals(5, m.worst(), 0);
    }

    @Test
    void theWorstPixelIsFoundByColumnAndRow() {
        Film image = new Film(3, 2);
        Film reference = new Film(3, 2);
        image.set(1, 0, 0.2, 0, 0);
        image.set(2, 1, 0, 0, -0.7); // the worst: column 2, row 1, in the blue channel
        image.set(0, 1, 0.5, 0, 0);
        ErrorMetrics m = ErrorMetrics.compare(image, 1, reference);
        assertEquals(0.7, m.worst(), 1e-7);
        assertEquals(2, m.worstX());
        assertEquals(1, m.worstY());
    }

    @Test
    void identicalImagesHaveNoError() {
        Film[] f = twoPixels();
        ErrorMetrics m = ErrorMetrics.compare(f[1], 1, f[1]);
        assertEquals(0, m.rmse(), 0);
        assertEquals(0, m.relativeMse(), 0);
        assertEquals(0, m.worst(), 0);
    }

    @Test
    void aBlackReferenceHasNoRelativeRmse() {
        Film[] f = twoPixels();
        ErrorMetrics m = ErrorMetrics.compare(f[0], 1, new Film(2, 1));
        assertTrue(Double.isNaN(m.relativeRmse()));
        assertEquals(Math.sqrt(14.0 / 6), m.rmse(), 1e-15);
        assertEquals(14 / 0.01 / 6, m.relativeMse(), 1e-9);
    }

    @Test
    void sizesMustMatch() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> ErrorMetrics.compare(new Film(4, 3), 1, new Film(3, 4)));
        assertTrue(e.getMessage().contains("4x3") && e.getMessage().contains("3x4"), e.getMessage());
    }
}

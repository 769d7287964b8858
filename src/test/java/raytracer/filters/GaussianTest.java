package raytracer.filters;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The Gaussian's weights against its formula, its table and its reach. */
class GaussianTest {
    @Test
    void theGaussianIsMitsubasDefault() {
        Gaussian g = (Gaussian) Filters.byName("gaussian");
        assertEquals(0.5, g.stddev());
        assertEquals(2.0, g.radius(), "cut off at 4 standard deviations");
        // w(d) = exp(-d^2 / (2 sigma^2)) - exp(-r^2 / (2 sigma^2)) with sigma = 0.5, r = 2: exp(-2 d^2) - exp(-8)
        for (double d : new double[] {0, 0.25, 0.5, 1, 1.5, 1.99}) {
            assertEquals(Math.exp(-2 * d * d) - Math.exp(-8), g.exactWeight(d), 1e-15, "d = " + d);
        }
        assertEquals(0, g.exactWeight(2));
        assertEquals(0, g.exactWeight(2.5));
    }

    @Test
    void theTableGivesTheFormulaWithinTheInterpolationBound() {
        SplittableRandom random = new SplittableRandom(7);
        for (double stddev : new double[] {Gaussian.MIN_STDDEV, 0.5, 1, Gaussian.MAX_STDDEV}) {
            Gaussian f = new Gaussian(stddev);
            double worst = 0;
            for (int i = 0; i < 100_000; i++) {
                double d = (random.nextDouble() * 2 - 1) * 1.2 * f.radius();
                worst = Math.max(worst, Math.abs(f.weight(d) - f.exactWeight(d)));
            }
            // at the table's nodes the formula itself, up to the rounding of d * 1024 / r
            for (int i = 0; i <= 1024; i += 17) {
                double node = i * f.radius() / 1024;
                assertEquals(f.exactWeight(node), f.weight(node), 1e-12, "stddev " + stddev + ", node " + i);
            }
            // linear interpolation over steps h = r / 1024 = sigma / 256: error at most h^2 / 8 max|w''|,
            // and max|w''| = 1 / sigma^2, so 1 / (8 * 256^2) = 1.9e-6 whatever sigma
            assertTrue(worst <= 1.0 / (8 * 256 * 256) + 1e-15, "stddev " + stddev + ": table off by " + worst);
            assertTrue(worst > 0, "the table is read, not the formula");
            assertEquals(0, f.weight(f.radius()));
            assertEquals(0, f.weight(Double.NaN), "a NaN distance weighs nothing");
        }
    }

    @Test
    void theReachIsTheFarthestPixelASampleCanWeigh() {
        for (double stddev = Gaussian.MIN_STDDEV; stddev <= Gaussian.MAX_STDDEV; stddev += 0.01) {
            Gaussian f = new Gaussian(stddev);
            int farthest = 0;
            // a sample at fraction u of its pixel, k pixels over from the one whose weight we take
            for (int k = 0; k < 20; k++) {
                for (int step = 0; step < 1000; step++) {
                    double u = step / 1000.0;
                    if (f.exactWeight(k + 0.5 - u) > 0) {
                        farthest = Math.max(farthest, k);
                    }
                }
            }
            assertTrue(f.reach() >= farthest, "stddev " + stddev + ": reach " + f.reach() + " below " + farthest);
            assertTrue(f.reach() <= farthest + 1, "stddev " + stddev + ": reach " + f.reach() + " wastes pixels past " + farthest);
        }
        assertEquals(2, Filters.byName("gaussian").reach());
    }

    @Test
    void badFiltersAreRefusedWithTheAllowedValues() {
        IllegalArgumentException name = assertThrows(IllegalArgumentException.class, () -> Filters.byName("mitchell"));
        assertEquals("unknown filter 'mitchell'; allowed: " + String.join(", ", Filters.names()), name.getMessage());
        assertTrue(name.getMessage().startsWith("unknown filter 'mitchell'; allowed: box, gaussian"), name.getMessage());
        for (double bad : new double[] {0, 0.1, 2.5, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Gaussian(bad));
            assertTrue(e.getMessage().contains("0.2 to 2"), e.getMessage());
        }
    }
}

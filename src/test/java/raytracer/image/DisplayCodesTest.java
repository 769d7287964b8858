package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.PropertyCheck;

/** The code table must give ToneMap.toByte's code for every value: at its steps, beside them and anywhere. */
class DisplayCodesTest {

    @Test
    void codesEqualToneMapsAtEveryStepAndBesideIt() {
        for (boolean srgb : new boolean[] {true, false}) {
            DisplayCodes codes = new DisplayCodes(1, srgb);
            // every code boundary, found here by bisection over the value (the class bisects the
            // bit patterns), checked on both sides
            for (int k = 1; k <= 255; k++) {
                double lo = 0;
                double hi = 1;
                while (Math.nextUp(lo) < hi) {
                    double mid = lo + (hi - lo) / 2;
                    if (ToneMap.toByte(mid, 1, srgb) >= k) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                for (double x : new double[] {Math.nextDown(hi), hi, Math.nextUp(hi), lo}) {
                    assertEquals(ToneMap.toByte(x, 1, srgb), codes.code(x), "value " + x + " (srgb " + srgb + ")");
                }
            }
            assertEquals(0, codes.code(0.0), "zero");
            assertEquals(ToneMap.toByte(Double.MIN_VALUE, 1, srgb), codes.code(Double.MIN_VALUE), "the least positive value");
        }
    }

    @Test
    void codesEqualToneMapsForAnyRadianceAndExposure() {
        PropertyCheck.forAll("display codes = toByte", 2_000, random -> {
            double exposure = PropertyCheck.logUniform(random, 1e-3, 1e3);
            boolean srgb = random.nextBoolean();
            DisplayCodes codes = new DisplayCodes(exposure, srgb);
            for (int i = 0; i < 500; i++) {
                double linear = switch (random.nextInt(6)) {
                    case 0 -> -random.nextDouble();
                    case 1 -> Double.NaN;
                    case 2 -> random.nextBoolean() ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
                    default -> random.nextDouble() * 1.2 / exposure;
                };
                assertEquals(ToneMap.toByte(linear, exposure, srgb), codes.code(linear),
                             "radiance " + linear + " at exposure " + exposure + " (srgb " + srgb + ")");
            }
        });
    }
}

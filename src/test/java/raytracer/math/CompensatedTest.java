package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The compensated residual |o + t d - c|^2 - r^2 against exact (BigDecimal) arithmetic. */
class CompensatedTest {
    private static BigDecimal exact(double v) {
        return new BigDecimal(v);
    }

    private static BigDecimal exactResidual(double[] o, double t, double[] d, double[] c, double r) {
        BigDecimal sum = exact(r).multiply(exact(r)).negate();
        for (int i = 0; i < 3; i++) {
            BigDecimal e = exact(o[i]).add(exact(t).multiply(exact(d[i]))).subtract(exact(c[i]));
            sum = sum.add(e.multiply(e));
        }
        return sum;
    }

    @Test
    void twoSumErrorIsTheExactRoundingError() {
        double a = 1e16;
        double b = 1;
        double s = a + b;
        assertEquals(1e16, s);
        assertEquals(1, Compensated.twoSumError(a, b, s));
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < 1000; i++) {
            double x = (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(40) - 20);
            double y = (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(40) - 20);
            double sum = x + y;
            assertEquals(0, exact(x).add(exact(y)).compareTo(exact(sum).add(exact(Compensated.twoSumError(x, y, sum)))),
                         x + " + " + y);
        }
    }

    @Test
    void pointsNearHugeSpheresKeepTheirResidualWithinTheBound() {
        // a point at height h above a sphere of radius r: the residual is about 2 r h, far below r^2
        SplittableRandom random = new SplittableRandom(11);
        for (int i = 0; i < 5_000; i++) {
            double r = Math.pow(10, 30 * random.nextDouble() - 5);
            double h = r * Math.pow(10, -random.nextDouble() * 25) * (random.nextBoolean() ? 1 : -1);
            double[] c = {r * (random.nextDouble() - 0.5), r * (random.nextDouble() - 0.5), r * (random.nextDouble() - 0.5)};
            double[] u = {random.nextDouble() - 0.5, random.nextDouble() - 0.5, random.nextDouble() - 0.5};
            double len = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            double[] d = {random.nextDouble() - 0.5, random.nextDouble() - 0.5, random.nextDouble() - 0.5};
            double t = random.nextBoolean() ? 0 : h * random.nextDouble();
            double[] o = new double[3];
            for (int k = 0; k < 3; k++) {
                o[k] = c[k] + (r + h) * u[k] / len - t * d[k];
            }
            double computed = Compensated.residual(o[0], o[1], o[2], t, d[0], d[1], d[2], c[0], c[1], c[2], r);
            BigDecimal expected = exactResidual(o, t, d, c, r);
            double bound = Compensated.errorBound(computed, r + h, r);
            // measured: the error stays below 3 u^2 (e^2 + r^2) besides the final rounding; the bound allows 256
            assertTrue(exact(computed).subtract(expected).abs().compareTo(exact(bound)) <= 0,
                       "r " + r + ", h " + h + ": " + computed + " against " + expected + ", bound " + bound);
        }
    }

    @Test
    void theResidualIsExactWhereThePlainFormulaHasNoDigitLeft() {
        // 1 unit above a sphere of radius 1e16 centred at (0, -1e16, 0): exactly 2e16 + 1
        double plain = Math.pow(1 - -1e16, 2) - 1e16 * 1e16;
        assertTrue(Math.abs(plain - (2e16 + 1)) > 1e15, "the plain formula: " + plain);
        assertEquals(2e16 + 1, Compensated.residual(0, 1, 0, 0, 0, 0, 0, 0, -1e16, 0, 1e16), 2);
    }
}

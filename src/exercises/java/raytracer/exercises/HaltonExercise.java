package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.Sampler;
import raytracer.math.Rng;
import raytracer.samplers.PureRandom;

/**
 * Exercise 1: the Halton sampler, point i = (phi_2(i), phi_3(i)) for i = 0 .. n-1, phi_b the
 * radical inverse in base b, shifted by one random offset per pattern and per axis, modulo 1
 * (Cranley and Patterson 1976), so that every pixel gets its own pattern and the estimate stays
 * unbiased. Checked against the radical inverses computed here, and against random points on an
 * integral with a known value.
 */
@Tag("exercise")
class HaltonExercise {
    private static Constructor<? extends Sampler> halton;

    @BeforeAll
    static void findTheClass() {
        halton = Student.constructor(1, "raytracer.samplers.Halton", Sampler.class);
    }

    private static Sampler halton() {
        return Student.create(halton);
    }

    /** phi_b(i): the base-b digits of i mirrored about the point. */
    private static double radicalInverse(int i, int base) {
        double value = 0;
        double digitWeight = 1.0 / base;
        for (int rest = i; rest > 0; rest /= base) {
            value += (rest % base) * digitWeight;
            digitWeight /= base;
        }
        return value;
    }

    /** The distance between two points of the circle [0, 1). */
    private static double circular(double a, double b) {
        double d = Math.abs(a - b) % 1;
        return Math.min(d, 1 - d);
    }

    @Test
    void everyCountIsSupported() {
        Sampler s = halton();
        for (int n = 1; n <= 100; n++) {
            assertEquals(n, s.supportedCount(n), "supportedCount(" + n + ") must be " + n + ": Halton points come in any number");
        }
    }

    @Test
    void pointsLieInTheUnitSquare() {
        Sampler s = halton();
        double[] xs = new double[256];
        double[] ys = new double[256];
        for (int seed = 0; seed < 200; seed++) {
            s.generate(256, new Rng(seed), xs, ys);
            for (int i = 0; i < 256; i++) {
                assertTrue(xs[i] >= 0 && xs[i] < 1 && ys[i] >= 0 && ys[i] < 1, "generate(256, new Rng(" + seed + ")): point " + i
                                                                                + " = (" + xs[i] + ", " + ys[i] + ") must lie in [0, 1)^2");
            }
        }
    }

    @Test
    void pointsAreTheRadicalInversesShiftedByOneOffsetPerAxis() {
        Sampler s = halton();
        int n = 100;
        double[] xs = new double[n];
        double[] ys = new double[n];
        for (int seed = 0; seed < 20; seed++) {
            s.generate(n, new Rng(seed), xs, ys);
            for (int i = 0; i < n; i++) {
                // point 0 is the offset itself, as phi(0) = 0
                String pattern = "generate(100, new Rng(" + seed + ")): ";
                assertEquals(0, circular(xs[i] - xs[0], radicalInverse(i, 2)), 1e-12, pattern + "x of point " + i
                             + " - x of point 0 must be phi_2(" + i + ") = " + radicalInverse(i, 2) + " modulo 1, got " + (xs[i] - xs[0]));
                assertEquals(0, circular(ys[i] - ys[0], radicalInverse(i, 3)), 1e-12, pattern + "y of point " + i
                             + " - y of point 0 must be phi_3(" + i + ") = " + radicalInverse(i, 3) + " modulo 1, got " + (ys[i] - ys[0]));
            }
        }
    }

    @Test
    void theOffsetsAreUniformIndependentAndDrawnFromTheGenerator() {
        Sampler s = halton();
        double[] xs = new double[4];
        double[] ys = new double[4];
        double[] again = new double[4];
        double[] againY = new double[4];
        int trials = 4000;
        double sumX = 0;
        double sumY = 0;
        int equal = 0;
        for (int seed = 0; seed < trials; seed++) {
            s.generate(4, new Rng(seed), xs, ys);
            s.generate(4, new Rng(seed), again, againY);
            assertArrayEquals(xs, again, "generate(4, new Rng(" + seed + ")) twice: the same generator state must give the same "
                                         + "pattern (draw the offsets from the rng given, nothing else)");
            sumX += xs[0];
            sumY += ys[0];
            equal += xs[0] == ys[0] ? 1 : 0;
        }
        double error = 4 * Math.sqrt(1.0 / 12 / trials);
        assertEquals(0.5, sumX / trials, error, "over " + trials + " seeds point 0's x, the x offset, must average 0.5 (uniform in "
                                                + "[0, 1)) to " + error);
        assertEquals(0.5, sumY / trials, error, "over " + trials + " seeds point 0's y, the y offset, must average 0.5 (uniform in "
                                                + "[0, 1)) to " + error);
        assertTrue(equal < trials / 100, "x and y need offsets of their own: they were equal for " + equal + " of " + trials
                                         + " seeds (fewer than " + trials / 100 + " allowed)");
    }

    @Test
    void itIntegratesASmoothFunctionBetterThanRandomPoints() {
        // the integral of x y over the unit square is 1/4; the reference solution's error is 0.28
        // times that of random points (the shift wraps points around, where x y jumps)
        double halton = rmsError(halton());
        double random = rmsError(new PureRandom());
        assertTrue(halton < 0.5 * random, "the integral of x y over the unit square with 64 points, 500 seeds: Halton's RMS error "
                                          + "must be below 0.5 times random points' (the reference solution: 0.28 times); got "
                                          + halton + " against " + random + ", " + halton / random + " times");
    }

    private static double rmsError(Sampler s) {
        int n = 64;
        double[] xs = new double[n];
        double[] ys = new double[n];
        double sum = 0;
        int trials = 500;
        for (int seed = 0; seed < trials; seed++) {
            s.generate(n, new Rng(seed), xs, ys);
            double estimate = 0;
            for (int i = 0; i < n; i++) {
                estimate += xs[i] * ys[i] / n;
            }
            sum += (estimate - 0.25) * (estimate - 0.25);
        }
        return Math.sqrt(sum / trials);
    }
}

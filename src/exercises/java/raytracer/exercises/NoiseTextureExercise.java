package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/**
 * Exercise 8: a solid texture of gradient noise (Perlin 1985 and 2002; Suffern, chapter 31, builds
 * lattice noise the same way from values instead of gradients). At the local hit point p, with
 * n(p / scale) the noise, the colour is low + (high - low) t, t = (1 + n) / 2 clamped to [0, 1].
 * Gradient noise is 0 at every lattice point, smooth, and its values spread around 0: that is
 * what is checked, since the gradients themselves are the student's choice.
 */
@Tag("exercise")
class NoiseTextureExercise {
    private static final RGBColor LOW = new RGBColor(0.1, 0.2, 0.3);
    private static final RGBColor HIGH = new RGBColor(0.9, 0.7, 0.5);
    private static Constructor<? extends Texture> noise;

    private final Scratch scratch = new Scratch();

    @BeforeAll
    static void findTheClass() {
        noise = Student.constructor(8, "raytracer.textures.GradientNoise", Texture.class, RGBColor.class, RGBColor.class, double.class);
    }

    private static Texture noise(double scale) {
        return Student.create(noise, LOW, HIGH, scale);
    }

    /** t of the colour at the local point (x, y, z), read from the red channel; the world point is elsewhere. */
    private double t(Texture texture, double x, double y, double z) {
        ShadeRec sr = scratch.surfacePoint(x + 17.25, y - 3.5, z + 8.125, 0, 1, 0);
        sr.localHitPoint.set(x, y, z);
        MutableRgb out = new MutableRgb();
        texture.getColor(sr, out);
        double t = (out.r - LOW.r()) / (HIGH.r() - LOW.r());
        assertEquals(LOW.g() + t * (HIGH.g() - LOW.g()), out.g, 1e-12, "the colour lies between low and high");
        assertEquals(LOW.b() + t * (HIGH.b() - LOW.b()), out.b, 1e-12, "the colour lies between low and high");
        return t;
    }

    @Test
    void latticePointsGiveTheMiddleColour() {
        Texture texture = noise(0.5);
        for (int i = -3; i <= 3; i++) {
            for (int j = -3; j <= 3; j++) {
                assertEquals(0.5, t(texture, 0.5 * i, 0.5 * j, 0.5 * (i - j)), 1e-12,
                             "gradient noise is 0 at the lattice point (" + i + ", " + j + ", " + (i - j) + ") times the scale");
            }
        }
    }

    @Test
    void itStaysBetweenTheColoursAndSpreadsAroundTheMiddle() {
        Texture texture = noise(1);
        SplittableRandom random = new SplittableRandom(4);
        int n = 20_000;
        double sum = 0;
        double sumSquares = 0;
        double widest = 0;
        for (int i = 0; i < n; i++) {
            double t = t(texture, 100 * random.nextDouble() - 50, 100 * random.nextDouble() - 50, 100 * random.nextDouble() - 50);
            assertTrue(t >= 0 && t <= 1, "t = " + t + " is outside [0, 1]");
            sum += t;
            sumSquares += t * t;
            widest = Math.max(widest, Math.abs(t - 0.5));
        }
        double mean = sum / n;
        double deviation = Math.sqrt(sumSquares / n - mean * mean);
        assertEquals(0.5, mean, 0.02, "noise averages to 0");
        assertTrue(deviation > 0.05, "the texture hardly varies: standard deviation of t " + deviation);
        assertTrue(widest > 0.25, "the noise never strays far from 0: at most " + widest);
    }

    @Test
    void itIsContinuousWithAContinuousSlopeAcrossLatticePlanes() {
        Texture texture = noise(1);
        SplittableRandom random = new SplittableRandom(6);
        double h = 1e-4;
        for (int i = 0; i < 2000; i++) {
            double y = 10 * random.nextDouble();
            double z = 10 * random.nextDouble();
            double x = Math.floor(10 * random.nextDouble());
            // on either side of the plane x = integer
            double left = t(texture, x - 1e-9, y, z);
            double right = t(texture, x + 1e-9, y, z);
            assertEquals(left, right, 1e-7, "a jump at the lattice plane x = " + x);
            double slopeLeft = (t(texture, x - h, y, z) - t(texture, x - 2 * h, y, z)) / h;
            double slopeRight = (t(texture, x + 2 * h, y, z) - t(texture, x + h, y, z)) / h;
            assertEquals(slopeLeft, slopeRight, 0.01, "a kink at the lattice plane x = " + x);
        }
    }

    @Test
    void theScaleStretchesTheSamePattern() {
        Texture unit = noise(1);
        Texture stretched = noise(2.5);
        SplittableRandom random = new SplittableRandom(8);
        for (int i = 0; i < 200; i++) {
            double x = 20 * random.nextDouble();
            double y = 20 * random.nextDouble();
            double z = 20 * random.nextDouble();
            assertEquals(t(unit, x, y, z), t(stretched, 2.5 * x, 2.5 * y, 2.5 * z), 1e-12,
                         "scale 2.5 stretches the pattern: t at (" + 2.5 * x + ", " + 2.5 * y + ", " + 2.5 * z + ") with scale 2.5 must equal "
                         + "t at (" + x + ", " + y + ", " + z + ") with scale 1");
        }
    }

    @Test
    void everyInstanceShowsTheSamePattern() {
        Texture a = noise(1);
        Texture b = noise(1);
        for (int i = 0; i < 100; i++) {
            assertEquals(t(a, 0.37 * i, 1.1 * i, -0.6 * i), t(b, 0.37 * i, 1.1 * i, -0.6 * i), 0,
                         "no random state of its own: the same scene must give the same image");
        }
    }

    @Test
    void aScaleOfZeroIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> noise(0), "GradientNoise(..., 0): a scale must be positive (IllegalArgumentException)");
        assertThrows(IllegalArgumentException.class, () -> noise(Double.NaN),
                     "GradientNoise(..., NaN): a scale must be positive (IllegalArgumentException)");
    }
}

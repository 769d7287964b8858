package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The plain-Java atan2 against Math.atan2 (fdlibm) over every octant and scales, and at the axes. */
class ArcTangentTest {

    @Test
    void matchesMathAtan2() {
        SplittableRandom random = new SplittableRandom(2);
        double worst = 0;
        for (int i = 0; i < 2_000_000; i++) {
            double x = random.nextDouble(-1, 1) * Math.exp(random.nextDouble(-40, 40));
            double y = random.nextDouble(-1, 1) * Math.exp(random.nextDouble(-40, 40));
            double exact = Math.atan2(y, x);
            double error = Math.abs(ArcTangent.atan2(y, x) - exact);
            // a few ulps of the angle, or absolutely a few 1e-16 where the angle is tiny
            worst = Math.max(worst, error / Math.max(Math.ulp(exact), 0x1p-53));
        }
        assertEquals(0, worst, 4, "worst error in ulps of the angle");
    }

    @Test
    void axesAndSignedZeros() {
        double[][] cases = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}, {-0.0, 1}, {-0.0, -1}, {0, 0}, {-0.0, 0}, {0, -0.0}, {1, 1}, {-1, -1},
                            {1e-300, -1}, {-1e-300, -1}, {5, 5 * 0.41421356237309503}};
        for (double[] c : cases) {
            assertEquals(Math.atan2(c[0], c[1]), ArcTangent.atan2(c[0], c[1]), 3e-16, c[0] + ", " + c[1]);
        }
    }
}

package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.PropertyCheck;
import raytracer.core.ShadeRec;
import raytracer.math.Ray;
import raytracer.math.ShearedRay;

/**
 * The watertight test joins its sign tests without Math.min/max and without short-circuits
 * (Watertight.intersect): its distance and barycentrics must equal, bit for bit, those of the test
 * as Woop, Benthin and Wald write it, on rays through edges and vertices as well as inside and
 * outside.
 */
class WatertightTest {
    private final ShadeRec sr = new HitTesting().record();

    @Test
    void theTestGivesTheDistanceAndBarycentricsOfThePaperBitForBit() {
        PropertyCheck.forAll("watertight = paper's test", 20_000, random -> {
            // small integers: rays through vertices and along edges happen often, as do zero edge functions
            double[] v = new double[9];
            for (int i = 0; i < 9; i++) {
                v[i] = random.nextInt(-3, 4);
            }
            Ray ray = new Ray().set(random.nextInt(-4, 5), random.nextInt(-4, 5), random.nextInt(-4, 5),
                                    random.nextInt(-2, 3), random.nextInt(-2, 3), random.nextInt(-2, 3) + 0.5);
            double tMax = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : random.nextInt(1, 8);
            ShearedRay sheared = new ShearedRay().load(ray);
            sr.b1 = Double.NaN;
            sr.b2 = Double.NaN;
            double t = Watertight.intersect(sheared, v, 0, 3, 6, tMax, sr);
            double[] expected = paper(sheared, v, tMax);
            assertEquals(bits(expected[0]), bits(t), () -> "t " + t + " for the paper's " + expected[0]);
            if (t < Double.POSITIVE_INFINITY) {
                assertEquals(bits(expected[1]), bits(sr.b1), "b1");
                assertEquals(bits(expected[2]), bits(sr.b2), "b2");
            }
        });
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    /** Section 3 of the paper, in double precision: {t, b1, b2}, t = +infinity for a miss. */
    private static double[] paper(ShearedRay ray, double[] v, double tMax) {
        double[] z = new double[3];
        double[] x = new double[3];
        double[] y = new double[3];
        for (int i = 0; i < 3; i++) {
            z[i] = v[3 * i + ray.kz()] - ray.originZ();
            x[i] = v[3 * i + ray.kx()] - ray.originX() - ray.sx() * z[i];
            y[i] = v[3 * i + ray.ky()] - ray.originY() - ray.sy() * z[i];
        }
        double u = x[2] * y[1] - y[2] * x[1];
        double w1 = x[0] * y[2] - y[0] * x[2];
        double w2 = x[1] * y[0] - y[1] * x[0];
        double miss = Double.POSITIVE_INFINITY;
        if ((u < 0 || w1 < 0 || w2 < 0) && (u > 0 || w1 > 0 || w2 > 0)) {
            return new double[] {miss, 0, 0};
        }
        double det = u + w1 + w2;
        double t = (u * (ray.sz() * z[0]) + w1 * (ray.sz() * z[1]) + w2 * (ray.sz() * z[2])) / det;
        if (!(t > 0 && t < tMax)) {
            return new double[] {miss, 0, 0};
        }
        return new double[] {t, w1 / det, w2 / det};
    }
}

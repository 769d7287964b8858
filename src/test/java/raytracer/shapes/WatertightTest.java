package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.PropertyCheck;
import raytracer.core.ShadeRec;
import raytracer.math.Ray;
import raytracer.math.ShearedRay;

/**
 * The watertight test joins its sign tests without Math.min/max and without short-circuits
 * (Watertight.intersect): its distance and barycentrics must equal, bit for bit, those of the test
 * as Woop, Benthin and Wald write it, on rays through edges and vertices as well as inside and
 * outside, except where the paper's t lies within rounding of 0 (a ray starting on the
 * triangle's plane), which ours rejects. And a ray that starts on a triangle's plane, as one
 * spawned from a flat mesh on a coordinate plane does (its error bound along the normal is 0),
 * never hits it, at any scale or offset: the shadow acne of flat floors.
 */
class WatertightTest {
    private final ShadeRec sr = new HitTesting().record();

    @Test
    void theTestGivesTheDistanceAndBarycentricsOfThePaperBitForBit() {
        int[] rejected = new int[1];
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
            if (t == Double.POSITIVE_INFINITY && expected[0] < t) {
                // the coordinates are small integers: a t that is not rounding would be above 1e-3
                assertTrue(expected[0] < 1e-12, () -> "rejected the paper's t " + expected[0]);
                rejected[0]++;
                return;
            }
            assertEquals(bits(expected[0]), bits(t), () -> "t " + t + " for the paper's " + expected[0]);
            if (t < Double.POSITIVE_INFINITY) {
                assertEquals(bits(expected[1]), bits(sr.b1), "b1");
                assertEquals(bits(expected[2]), bits(sr.b2), "b2");
            }
        });
        assertTrue(rejected[0] > 0, "no ray started on its triangle's plane: the rejection was not tried");
    }

    /**
     * Rays leaving a point of a triangle (its hit point as the mesh completes it) towards a random
     * side: the triangle lies in a coordinate plane at 0 or elsewhere, or is tilted, at scales 1e-4
     * to 1e6 and offsets up to 1e6; the ray starts where ShadeRec.spawnRay puts it. Neither the
     * closest-hit test nor the shadow test may find the triangle again.
     */
    @Test
    void aRayLeavingATriangleNeverHitsItAgain() {
        PropertyCheck.forAll("a ray leaving a triangle never hits it", 20_000, random -> {
            double scale = PropertyCheck.logUniform(random, 1e-4, 1e6);
            double offset = random.nextInt(3) == 0 ? 0 : PropertyCheck.logUniform(random, 1e-3, 1e6) * (random.nextBoolean() ? 1 : -1);
            int flat = random.nextInt(4); // 0, 1, 2: normal along x, y, z; 3: tilted
            double[] v = new double[9];
            for (int i = 0; i < 9; i++) {
                v[i] = offset + scale * random.nextDouble(-10, 10);
            }
            if (flat < 3) {
                double level = random.nextBoolean() ? 0 : offset;
                v[flat] = level;
                v[3 + flat] = level;
                v[6 + flat] = level;
            }
            double b1 = random.nextDouble(0.05, 0.9);
            double b2 = random.nextDouble(0.05, 0.95 - b1);
            Watertight.interpolate(v, 0, 3, 6, 1 - b1 - b2, b1, b2, sr);
            double[] e1 = {v[3] - v[0], v[4] - v[1], v[5] - v[2]};
            double[] e2 = {v[6] - v[0], v[7] - v[1], v[8] - v[2]};
            sr.geometricNormal.set(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]).normalize();
            double[] d = PropertyCheck.unitVector(random);
            Ray ray = sr.spawnRay(d[0], d[1], d[2], new Ray());
            ShearedRay sheared = new ShearedRay().load(ray);
            double t = Watertight.intersect(sheared, v, 0, 3, 6, Double.POSITIVE_INFINITY, sr);
            assertEquals(Double.POSITIVE_INFINITY, t, () -> "hit its own triangle at t " + t + " from " + ray);
            assertFalse(Watertight.crossesWithin(sheared, v, 0, 3, 6, Double.POSITIVE_INFINITY), () -> "shadowed itself from " + ray);
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

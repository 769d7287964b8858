package raytracer.brdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vec3;
import raytracer.math.Vector3D;

/**
 * Glossy sampling estimates the reflected radiance integral of f cos(theta_i) L(wi) over the
 * hemisphere: the Monte Carlo average of {@link GlossySpecular#sample} weights must converge to a
 * quadrature of the same lobe, including where the lobe dips below the surface.
 */
class GlossySamplingTest {

    /** A smooth incident radiance, brighter towards +x and overhead. */
    private static double radiance(Vec3 w) {
        return 1 + 0.8 * w.x + 0.5 * w.z * w.z;
    }

    @ParameterizedTest
    @CsvSource({"1, 0", "20, 30", "20, 75", "200, 60", "1000, 10"})
    void monteCarloConvergesToTheQuadratureOfTheLobe(double e, double viewDegrees) {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.normal.set(0, 0, 1);
        double theta = Math.toRadians(viewDegrees);
        Vec3 wo = new Vec3().set(-Math.sin(theta), 0, Math.cos(theta));
        GlossySpecular lobe = new GlossySpecular(1, RGBColor.WHITE, e, false);

        SplittableRandom random = new SplittableRandom(11);
        int n = 400_000;
        double sum = 0;
        double sum2 = 0;
        Vec3 wi = new Vec3();
        for (int i = 0; i < n; i++) {
            double w = lobe.sample(sr, wo, random.nextDouble(), random.nextDouble(), wi);
            double v = w > 0 ? w * radiance(wi) : 0;
            sum += v;
            sum2 += v * v;
        }
        double mean = sum / n;
        double error = Math.sqrt(Math.max(0, sum2 / n - mean * mean) / n);

        // quadrature in the frame of the mirror direction r: f = cos^e(alpha), alpha from r
        double[] r = {Math.sin(theta), 0, Math.cos(theta)};
        double[] a = {Math.cos(theta), 0, -Math.sin(theta)};
        double[] b = {0, 1, 0};
        int steps = 3000;
        int phis = 720;
        double alphaMax = Math.min(Math.PI / 2, 12 / Math.sqrt(e + 1));
        double integral = 0;
        for (int i = 0; i < steps; i++) {
            double alpha = (i + 0.5) * alphaMax / steps;
            double cosE = Math.pow(Math.cos(alpha), e);
            for (int j = 0; j < phis; j++) {
                double phi = (j + 0.5) * 2 * Math.PI / phis;
                double x = Math.sin(alpha) * Math.cos(phi);
                double y = Math.sin(alpha) * Math.sin(phi);
                double z = Math.cos(alpha);
                wi.set(x * a[0] + y * b[0] + z * r[0], x * a[1] + y * b[1] + z * r[1], x * a[2] + y * b[2] + z * r[2]);
                if (wi.z <= 0) {
                    continue;
                }
                integral += cosE * wi.z * radiance(wi) * Math.sin(alpha) * (alphaMax / steps) * (2 * Math.PI / phis);
            }
        }
        assertEquals(integral, mean, 4 * error + 1e-4 * integral, "e=" + e + " view " + viewDegrees + ": " + mean + " +- " + error);
        assertTrue(error < 0.01 * integral, "the estimate should be tight: " + error + " of " + integral);
    }
}

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
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * The Phong lobe's sample_f / pdf pair: sampling estimates the reflected radiance integral of
 * f cos(theta_i) L(wi) over the hemisphere, so the Monte Carlo average of the weights of
 * {@link GlossySpecular#sampleF}, and that of f cos / pdf evaluated independently at the sampled
 * directions, must converge to a quadrature of the same lobe, including where it dips below the
 * surface; and the density must integrate to 1.
 */
class GlossySamplingTest {

    /** A smooth incident radiance, brighter towards +x and overhead. */
    private static double radiance(MutableVec3 w) {
        return 1 + 0.8 * w.x + 0.5 * w.z * w.z;
    }

    /** A hit on the plane z = 0 with normal +z. */
    private static ShadeRec hit() {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.normal.set(0, 0, 1);
        return sr;
    }

    /** The viewer's direction, {@code degrees} from the normal in the xz plane. */
    private static MutableVec3 viewer(double degrees) {
        double theta = Math.toRadians(degrees);
        return new MutableVec3().set(-Math.sin(theta), 0, Math.cos(theta));
    }

    /** A function of a direction wi and the cosine of its angle alpha from the mirror direction. */
    private interface Integrand {
        double at(MutableVec3 wi, double cosAlpha);
    }

    /**
     * Integrates {@code integrand}(wi, cos(alpha)) sin(alpha) over the hemisphere around the mirror direction r
     * of the viewer (alpha from r), in the frame (a, b, r); directions below the surface count
     * only when {@code belowToo}.
     */
    private static double quadratureAroundMirror(double viewDegrees, double e, boolean belowToo, int steps, int phis,
                                                 Integrand integrand) {
        double theta = Math.toRadians(viewDegrees);
        double[] r = {Math.sin(theta), 0, Math.cos(theta)};
        double[] a = {Math.cos(theta), 0, -Math.sin(theta)};
        double[] b = {0, 1, 0};
        // cos^e(alpha) < exp(-70) beyond 12 / sqrt(e + 1)
        double alphaMax = Math.min(Math.PI / 2, 12 / Math.sqrt(e + 1));
        MutableVec3 wi = new MutableVec3();
        double integral = 0;
        for (int i = 0; i < steps; i++) {
            double alpha = (i + 0.5) * alphaMax / steps;
            for (int j = 0; j < phis; j++) {
                double phi = (j + 0.5) * 2 * Math.PI / phis;
                double x = Math.sin(alpha) * Math.cos(phi);
                double y = Math.sin(alpha) * Math.sin(phi);
                double z = Math.cos(alpha);
                wi.set(x * a[0] + y * b[0] + z * r[0], x * a[1] + y * b[1] + z * r[1], x * a[2] + y * b[2] + z * r[2]);
                if (wi.z <= 0 && !belowToo) {
                    continue;
                }
                integral += integrand.at(wi, z) * Math.sin(alpha) * (alphaMax / steps) * (2 * Math.PI / phis);
            }
        }
        return integral;
    }

    @ParameterizedTest
    @CsvSource({"1, 0", "20, 30", "20, 75", "200, 60", "1000, 10"})
    void sampleWeightsConvergeToTheQuadratureOfTheLobe(double e, double viewDegrees) {
        ShadeRec sr = hit();
        MutableVec3 wo = viewer(viewDegrees);
        GlossySpecular lobe = new GlossySpecular(1, RGBColor.WHITE, e, false);
        SplittableRandom random = new SplittableRandom(11);
        int n = 400_000;
        double sum = 0;
        double sum2 = 0;
        double sumIndependent = 0;
        MutableVec3 wi = new MutableVec3();
        MutableRgb weight = new MutableRgb();
        MutableRgb f = new MutableRgb();
        for (int i = 0; i < n; i++) {
            boolean above = lobe.sampleF(sr, wo, random.nextDouble(), random.nextDouble(), wi, weight);
            assertEquals(above, wi.z > 0, "false exactly below the surface");
            if (!above) {
                assertEquals(0, weight.r + weight.g + weight.b, "a black weight below the surface");
                continue;
            }
            // the weight is f cos / pdf, with f and pdf evaluated on their own at the same wi
            lobe.f(sr, wo, wi, f);
            double pdf = lobe.pdf(sr, wo, wi);
            double independent = f.r * wi.z / pdf;
            assertEquals(independent, weight.r, 1e-9 * independent, "weight of sample " + i);
            double v = weight.r * radiance(wi);
            sum += v;
            sum2 += v * v;
            sumIndependent += independent * radiance(wi);
        }
        double mean = sum / n;
        double error = Math.sqrt(Math.max(0, sum2 / n - mean * mean) / n);
        // quadrature of f cos(theta_i) L with f = cos^e(alpha)
        double integral = quadratureAroundMirror(viewDegrees, e, false, 3000, 720, (w, cosAlpha) -> Math.pow(cosAlpha, e) * w.z * radiance(w));
        assertEquals(integral, mean, 4 * error + 1e-4 * integral, "e=" + e + " view " + viewDegrees + ": " + mean + " +- " + error);
        assertEquals(integral, sumIndependent / n, 4 * error + 1e-4 * integral, "f cos / pdf at the samples");
        assertTrue(error < 0.01 * integral, "the estimate should be tight: " + error + " of " + integral);
    }

    @ParameterizedTest
    @CsvSource({"1, 0", "20, 75", "1000, 10"})
    void pdfIntegratesToOneOverTheHemisphereAroundTheMirrorDirection(double e, double viewDegrees) {
        ShadeRec sr = hit();
        MutableVec3 wo = viewer(viewDegrees);
        GlossySpecular lobe = new GlossySpecular(0.7, RGBColor.WHITE, e, true);
        double total = quadratureAroundMirror(viewDegrees, e, true, 1000, 360, (w, cosAlpha) -> lobe.pdf(sr, wo, w));
        assertEquals(1, total, 1e-4, "e=" + e);
    }

    @ParameterizedTest
    @CsvSource({"1, 0", "20, 30", "200, 60"})
    void theNormalisedLobeWeighsByItsNormalisation(double e, double viewDegrees) {
        // same direction for the same (u, v): the weight scales by (e + 2) / (2 pi) exactly
        ShadeRec sr = hit();
        MutableVec3 wo = viewer(viewDegrees);
        GlossySpecular plain = new GlossySpecular(0.5, new RGBColor(1, 0.5, 0.25), e, false);
        GlossySpecular normalised = new GlossySpecular(0.5, new RGBColor(1, 0.5, 0.25), e, true);
        MutableVec3 w1 = new MutableVec3();
        MutableVec3 w2 = new MutableVec3();
        MutableRgb a = new MutableRgb();
        MutableRgb b = new MutableRgb();
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 1000; i++) {
            double u = random.nextDouble();
            double v = random.nextDouble();
            if (!plain.sampleF(sr, wo, u, v, w1, a)) {
                continue;
            }
            assertTrue(normalised.sampleF(sr, wo, u, v, w2, b));
            assertEquals(w1.x, w2.x, 0);
            assertEquals(a.r * (e + 2) / (2 * Math.PI), b.r, 1e-12 * b.r);
            assertEquals(0.5 * a.r, a.g, 1e-15, "coloured by cs");
        }
    }
}

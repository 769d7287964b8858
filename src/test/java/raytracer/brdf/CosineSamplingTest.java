package raytracer.brdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The BRDF interface's default sample_f / pdf, cosine sampling of the hemisphere, which Lambertian,
 * Ward and Blinn-Phong use: the weight is f cos / pdf at the sampled direction, the density
 * integrates to 1, and the average weight converges to the directional albedo by quadrature.
 */
class CosineSamplingTest {

    @Test
    void lambertianWeightIsItsAlbedoExactlyAndThePdfIsCosOverPi() {
        Lambertian lambertian = new Lambertian(0.7, new RGBColor(1, 0.5, 0.2));
        SplittableRandom random = new SplittableRandom(2);
        MutableVec3 wi = new MutableVec3();
        MutableRgb weight = new MutableRgb();
        for (int i = 0; i < 10_000; i++) {
            // a tilted normal, so that the frame around it is exercised too
            ShadeRec sr = Hits.withNormal(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
            MutableVec3 wo = new MutableVec3().set(sr.normal);
            if (!lambertian.sampleF(sr, wo, random.nextDouble(), random.nextDouble(), wi, weight)) {
                continue;
            }
            double cos = sr.normal.dot(wi);
            assertTrue(cos > 0);
            assertEquals(1, wi.length(), 1e-12);
            assertEquals(cos / Math.PI, lambertian.pdf(sr, wo, wi), 1e-15);
            // kd cd / pi * cos / (cos / pi) = kd cd
            assertEquals(0.7, weight.r, 1e-15);
            assertEquals(0.35, weight.g, 1e-15);
            assertEquals(0.14, weight.b, 1e-15);
        }
    }

    @Test
    void sampledDirectionsAreCosineDistributedAroundATiltedNormal() {
        // E[cos] = 2/3 and E[cos^2] = 1/2 under the density cos / pi
        ShadeRec sr = Hits.withNormal(0.3, -0.5, 0.8);
        Lambertian lambertian = new Lambertian(1, RGBColor.WHITE);
        MutableVec3 wi = new MutableVec3();
        MutableRgb weight = new MutableRgb();
        int grid = 300;
        double sum = 0;
        double sum2 = 0;
        for (int i = 0; i < grid; i++) {
            for (int j = 0; j < grid; j++) {
                assertTrue(lambertian.sampleF(sr, sr.normal, (i + 0.5) / grid, (j + 0.5) / grid, wi, weight));
                double cos = sr.normal.dot(wi);
                sum += cos;
                sum2 += cos * cos;
            }
        }
        assertEquals(2.0 / 3, sum / (grid * grid), 1e-4);
        assertEquals(0.5, sum2 / (grid * grid), 1e-4);
    }

    /**
     * For each fitted lobe the Monte Carlo albedo from the default sample_f matches a quadrature of
     * f cos(theta_i) over the hemisphere (in theta_i, phi_i; the fitted lobes are wide enough at
     * 30 degrees for 1,000 x 720 steps, and the Blinn-Phong presets with n above 1,000 are left to
     * FittedBrdfTest's half-vector quadrature).
     */
    @ParameterizedTest
    @EnumSource(value = FittedPreset.class, names = {"NICKEL_WARD", "NICKEL_WARD_DUER", "DELRIN_WARD", "DELRIN_WARD_DUER",
                                                      "DELRIN_BLINN_PHONG"})
    void monteCarloAlbedoMatchesTheQuadrature(FittedPreset preset) {
        BRDF lobe = preset.specular();
        ShadeRec sr = Hits.withNormal(0, 0, 1);
        MutableVec3 wo = Hits.direction(30, 0);
        MutableRgb f = new MutableRgb();
        MutableVec3 wi = new MutableVec3();
        int thetas = 1000;
        int phis = 720;
        double quadrature = 0;
        for (int i = 0; i < thetas; i++) {
            double theta = (i + 0.5) * (Math.PI / 2) / thetas;
            for (int j = 0; j < phis; j++) {
                double phi = (j + 0.5) * 2 * Math.PI / phis;
                wi.set(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
                lobe.f(sr, wo, wi, f);
                quadrature += f.r * Math.cos(theta) * Math.sin(theta) * (Math.PI / 2 / thetas) * (2 * Math.PI / phis);
            }
        }
        SplittableRandom random = new SplittableRandom(preset.ordinal());
        MutableRgb weight = new MutableRgb();
        int n = 200_000;
        double sum = 0;
        double sum2 = 0;
        double pdfIntegral = 0;
        for (int i = 0; i < n; i++) {
            if (lobe.sampleF(sr, wo, random.nextDouble(), random.nextDouble(), wi, weight)) {
                lobe.f(sr, wo, wi, f);
                assertEquals(f.r * wi.z / lobe.pdf(sr, wo, wi), weight.r, 1e-12 * weight.r + 1e-300, "weight = f cos / pdf");
                sum += weight.r;
                sum2 += weight.r * weight.r;
            }
        }
        double mean = sum / n;
        double error = Math.sqrt(Math.max(0, sum2 / n - mean * mean) / n);
        assertEquals(quadrature, mean, 4 * error + 1e-3 * quadrature, preset + ": " + mean + " +- " + error);
        // and the density integrates to 1 over the hemisphere
        for (int i = 0; i < thetas; i++) {
            double theta = (i + 0.5) * (Math.PI / 2) / thetas;
            wi.set(Math.sin(theta), 0, Math.cos(theta));
            pdfIntegral += lobe.pdf(sr, wo, wi) * 2 * Math.PI * Math.sin(theta) * (Math.PI / 2 / thetas);
        }
        assertEquals(1, pdfIntegral, 1e-6);
    }
}

package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * Exercise 7: a Cook-Torrance microfacet BRDF, f = D G F / (4 cos(theta_o) cos(theta_i)), with
 * a normalised distribution D (GGX or Beckmann) of roughness alpha, a masking term G (Smith's, or
 * Cook and Torrance's V-cavities) and Schlick's Fresnel F from the reflectance f0 at normal
 * incidence. Checked against the closed form at normal incidence, Schlick's formula, reciprocity,
 * energy conservation by quadrature, and its own sampling.
 */
@Tag("exercise")
class CookTorranceExercise {
    private static Constructor<? extends BRDF> cookTorrance;

    private final ShadeRec sr = new Scratch().surfacePoint(0, 0, 0, 0, 0, 1);

    @BeforeAll
    static void findTheClass() {
        cookTorrance = Student.constructor(7, "raytracer.brdf.CookTorrance", BRDF.class, RGBColor.class, double.class);
    }

    private static BRDF brdf(RGBColor f0, double alpha) {
        return Student.create(cookTorrance, f0, alpha);
    }

    private static MutableVec3 direction(double thetaDegrees, double phiDegrees) {
        double theta = Math.toRadians(thetaDegrees);
        double phi = Math.toRadians(phiDegrees);
        return new MutableVec3().set(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
    }

    private MutableRgb f(BRDF brdf, MutableVec3 wo, MutableVec3 wi) {
        MutableRgb out = new MutableRgb();
        brdf.f(sr, wo, wi, out);
        return out;
    }

    @Test
    void atNormalIncidenceItIsF0OverFourPiAlphaSquared() {
        // h = n: D = 1 / (pi alpha^2) for GGX and Beckmann alike, G = 1, F = f0, cosines 1
        RGBColor f0 = new RGBColor(0.04, 0.5, 0.95);
        MutableVec3 n = direction(0, 0);
        for (double alpha : new double[] {0.1, 0.3, 0.7}) {
            MutableRgb value = f(brdf(f0, alpha), n, n);
            double scale = 1 / (4 * Math.PI * alpha * alpha);
            String relation = "CookTorrance(f0 " + f0 + ", alpha " + alpha + "), wo = wi = n: f must be f0 / (4 pi alpha^2) = f0 times "
                              + scale + " (D = 1 / (pi alpha^2), G = 1, F = f0, both cosines 1), got " + value + "; ";
            assertEquals(f0.r() * scale, value.r, 1e-9 * scale, relation + "red");
            assertEquals(f0.g() * scale, value.g, 1e-9 * scale, relation + "green");
            assertEquals(f0.b() * scale, value.b, 1e-9 * scale, relation + "blue");
        }
    }

    @Test
    void roughnessOutsideZeroToOneIsRefused() {
        for (double alpha : new double[] {0, -0.5, 1.5, Double.NaN}) {
            assertThrows(IllegalArgumentException.class, () -> brdf(RGBColor.WHITE, alpha),
                         "CookTorrance(white, " + alpha + "): a roughness outside (0, 1] must be refused (IllegalArgumentException)");
        }
    }

    @Test
    void fresnelFollowsSchlick() {
        // wo and wi mirrored about the normal: h = n, so only F depends on f0, with cos(theta_d) = cos(theta)
        BRDF glass = brdf(RGBColor.gray(0.04), 0.3);
        BRDF white = brdf(RGBColor.gray(1), 0.3);
        for (double theta : new double[] {0, 30, 60, 80, 89}) {
            MutableVec3 wo = direction(theta, 0);
            MutableVec3 wi = direction(theta, 180);
            double expected = 0.04 + 0.96 * Math.pow(1 - Math.cos(Math.toRadians(theta)), 5);
            assertEquals(expected, f(glass, wo, wi).g / f(white, wo, wi).g, 1e-9, "F at " + theta + " degrees");
        }
    }

    @Test
    void itIsReciprocalNonNegativeAndBlackBelowTheSurface() {
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < 5000; i++) {
            BRDF brdf = brdf(new RGBColor(random.nextDouble(), random.nextDouble(), random.nextDouble()),
                             0.02 + 0.98 * random.nextDouble());
            MutableVec3 wo = direction(Math.toDegrees(Math.acos(random.nextDouble())), 360 * random.nextDouble());
            MutableVec3 wi = direction(Math.toDegrees(Math.acos(random.nextDouble())), 360 * random.nextDouble());
            MutableRgb forth = f(brdf, wo, wi);
            MutableRgb back = f(brdf, wi, wo);
            assertTrue(forth.r >= 0 && forth.g >= 0 && forth.b >= 0 && Double.isFinite(forth.r + forth.g + forth.b),
                       "f must be finite and non-negative, got " + forth);
            assertEquals(forth.g, back.g, 1e-10 * (1 + forth.g), "reciprocity, f(wo, wi) = f(wi, wo), for wo " + wo + ", wi " + wi
                                                                 + ": got " + forth.g + " and " + back.g);
            MutableVec3 below = new MutableVec3().set(wi.x, wi.y, -wi.z);
            assertTrue(f(brdf, wo, below).isBlack() && f(brdf, below, wo).isBlack(),
                       "f must be black when either direction is below the surface (wo " + wo + ", wi " + below + ")");
        }
        MutableRgb grazing = f(brdf(RGBColor.WHITE, 0.1), direction(89.9999, 0), direction(89.9999, 180));
        assertTrue(Double.isFinite(grazing.g) && grazing.g >= 0, "finite at grazing angles, got " + grazing);
    }

    @Test
    void itReflectsAtMostWhatArrivesAndNearlyAllOfItWhenSmooth() {
        for (double alpha : new double[] {0.2, 0.5, 1.0}) {
            BRDF brdf = brdf(RGBColor.WHITE, alpha);
            for (double theta : new double[] {0, 45, 75, 85}) {
                double albedo = albedo(brdf, direction(theta, 0));
                assertTrue(albedo <= 1.005, "alpha " + alpha + ", view at " + theta + " degrees reflects " + albedo + " > 1");
                if (alpha == 0.2 && theta == 0) {
                    assertTrue(albedo > 0.9, "a smooth white surface seen head-on reflects nearly all, got " + albedo
                                             + ": is D normalised (its projected integral 1)?");
                }
            }
        }
    }

    @Test
    void sampleFDrawsWhatFAndPdfSay() {
        BRDF brdf = brdf(RGBColor.WHITE, 0.3);
        SplittableRandom random = new SplittableRandom(3);
        for (double theta : new double[] {0, 50, 80}) {
            MutableVec3 wo = direction(theta, 30);
            double sum = 0;
            double sumSquares = 0;
            int n = 200_000;
            MutableVec3 wi = new MutableVec3();
            MutableRgb weight = new MutableRgb();
            for (int i = 0; i < n; i++) {
                if (brdf.sampleF(sr, wo, random.nextDouble(), random.nextDouble(), wi, weight)) {
                    double pdf = brdf.pdf(sr, wo, wi);
                    double expected = f(brdf, wo, wi).g * wi.z / pdf;
                    assertEquals(expected, weight.g, 1e-9 * (1 + expected), "the weight is f cos(theta_i) / pdf");
                    assertEquals(1, wi.length(), 1e-12, "a sampled direction has unit length");
                } else {
                    assertTrue(weight.isBlack(), "a rejected sample weighs nothing");
                }
                sum += weight.g;
                sumSquares += weight.g * weight.g;
            }
            double mean = sum / n;
            double error = Math.sqrt((sumSquares / n - mean * mean) / n);
            double albedo = albedo(brdf, wo);
            assertEquals(albedo, mean, 4 * error + 0.002 * albedo, "the mean weight estimates the albedo at " + theta + " degrees");
        }
    }

    /** The directional albedo, the integral of f cos(theta_i) over the hemisphere, by the midpoint rule in (cos(theta), phi). */
    private double albedo(BRDF brdf, MutableVec3 wo) {
        int steps = 600;
        double sum = 0;
        MutableVec3 wi = new MutableVec3();
        MutableRgb out = new MutableRgb();
        for (int i = 0; i < steps; i++) {
            double mu = (i + 0.5) / steps;
            double sin = Math.sqrt(1 - mu * mu);
            for (int j = 0; j < steps; j++) {
                double phi = 2 * Math.PI * (j + 0.5) / steps;
                wi.set(sin * Math.cos(phi), sin * Math.sin(phi), mu);
                brdf.f(sr, wo, wi, out);
                sum += out.g * mu;
            }
        }
        return sum * 2 * Math.PI / ((double) steps * steps);
    }
}

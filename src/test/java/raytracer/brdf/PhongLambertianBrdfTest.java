package raytracer.brdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cameras.Pinhole;
import raytracer.core.BRDF;
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
 * The report's own BRDFs, Lambertian and Phong (eq. 1, unnormalised and normalised), have the
 * properties every BRDF needs: non-negative, reciprocal, finite at grazing angles, and a directional
 * albedo (the integral of f cos(theta_i) over the hemisphere, by quadrature) that matches its closed
 * form at normal incidence and never exceeds it: kd for Lambertian, ks for the normalised lobe,
 * ks 2 pi / (e + 2) for the report's unnormalised one.
 */
class PhongLambertianBrdfTest {
    private static ShadeRec shadeRec() {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.normal.set(0, 0, 1);
        return sr;
    }

    private static MutableVec3 direction(double thetaDeg, double phiDeg) {
        double t = Math.toRadians(thetaDeg);
        double p = Math.toRadians(phiDeg);
        return new MutableVec3().set(Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t));
    }

    private static double f(BRDF brdf, ShadeRec sr, MutableVec3 wo, MutableVec3 wi) {
        MutableRgb out = new MutableRgb();
        brdf.f(sr, wo, wi, out);
        return out.r;
    }

    private static BRDF[] brdfs(double e) {
        return new BRDF[] {new Lambertian(0.8, RGBColor.WHITE), new GlossySpecular(0.8, RGBColor.WHITE, e, false),
            new GlossySpecular(0.8, RGBColor.WHITE, e, true)};
    }

    @ParameterizedTest
    @ValueSource(doubles = {1, 20, 1000})
    void nonNegativeReciprocalAndFiniteAtGrazingAngles(double e) {
        ShadeRec sr = shadeRec();
        SplittableRandom r = new SplittableRandom(3);
        for (BRDF brdf : brdfs(e)) {
            for (int i = 0; i < 20_000; i++) {
                MutableVec3 a = direction(r.nextDouble(0, 90), r.nextDouble(0, 360));
                MutableVec3 b = direction(r.nextDouble(0, 90), r.nextDouble(0, 360));
                double ab = f(brdf, sr, a, b);
                double ba = f(brdf, sr, b, a);
                assertTrue(ab >= 0, "negative");
                assertEquals(ab, ba, 1e-12 * Math.max(1, ab), "reciprocity");
            }
            for (double eps : new double[] {1e-3, 1e-6, 1e-9, 1e-12}) {
                for (double phi : new double[] {0, 90, 180}) {
                    double v = f(brdf, sr, direction(90 - eps, 0), direction(90 - eps, phi));
                    assertTrue(Double.isFinite(v) && v >= 0, brdf + " at " + eps + ": " + v);
                }
            }
        }
    }

    /**
     * Albedo by quadrature in the frame of the mirror direction r of wo, where the Phong lobe is
     * cos^e(alpha); the steps in alpha follow the lobe's width 1 / sqrt(e + 1).
     */
    private static double albedo(BRDF brdf, ShadeRec sr, double e, double thetaO) {
        double t = Math.toRadians(thetaO);
        MutableVec3 wo = new MutableVec3().set(-Math.sin(t), 0, Math.cos(t));
        double[] rr = {Math.sin(t), 0, Math.cos(t)};
        double[] a = {Math.cos(t), 0, -Math.sin(t)};
        double[] b = {0, 1, 0};
        boolean lambertian = brdf instanceof Lambertian;
        double alphaMax = lambertian ? Math.PI : Math.min(Math.PI / 2, 14 / Math.sqrt(e + 1));
        int steps = 2000;
        int phis = 720;
        double sum = 0;
        MutableVec3 wi = new MutableVec3();
        for (int i = 0; i < steps; i++) {
            double alpha = (i + 0.5) * alphaMax / steps;
            for (int j = 0; j < phis; j++) {
                double phi = (j + 0.5) * 2 * Math.PI / phis;
                double x = Math.sin(alpha) * Math.cos(phi);
                double y = Math.sin(alpha) * Math.sin(phi);
                double z = Math.cos(alpha);
                wi.set(x * a[0] + y * b[0] + z * rr[0], x * a[1] + y * b[1] + z * rr[1], x * a[2] + y * b[2] + z * rr[2]);
                if (wi.z <= 0) {
                    continue;
                }
                sum += f(brdf, sr, wo, wi) * wi.z * Math.sin(alpha) * (alphaMax / steps) * (2 * Math.PI / phis);
            }
        }
        return sum;
    }

    @ParameterizedTest
    @CsvSource({"1", "20", "1000"})
    void albedoMatchesItsClosedFormAndNeverExceedsIt(double e) {
        ShadeRec sr = shadeRec();
        BRDF[] all = brdfs(e);
        double[] closedForm = {0.8, 0.8 * 2 * Math.PI / (e + 2), 0.8};
        for (int k = 0; k < all.length; k++) {
            assertEquals(closedForm[k], albedo(all[k], sr, e, 0), 2e-3 * closedForm[k], "normal incidence, " + k + ", e=" + e);
            for (double thetaO : new double[] {30, 60, 85}) {
                double v = albedo(all[k], sr, e, thetaO);
                assertTrue(v <= closedForm[k] * (1 + 2e-3), k + " at " + thetaO + ": " + v + " > " + closedForm[k]);
                assertTrue(v > 0, "reflects something");
            }
        }
        // the normalised lobe conserves energy: with ks <= 1 it never reflects more than it receives
        assertTrue(albedo(new GlossySpecular(1, RGBColor.WHITE, e, true), sr, e, 40) <= 1 + 2e-3);
    }
}

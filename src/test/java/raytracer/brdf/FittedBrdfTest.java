package raytracer.brdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import raytracer.math.MutableVec3;

/** Ward, Ward-Duer and Blinn-Phong with the report's fitted presets: the properties a BRDF must have. */
class FittedBrdfTest {
    private static final MutableVec3 N = new MutableVec3().set(0, 0, 1);

    private static double lobe(FittedPreset p, MutableVec3 wo, MutableVec3 wi) {
        return p.model() == FittedPreset.Model.BLINN_PHONG
            ? ((BlinnPhong) p.specular()).value(N, wo, wi)
            : ((Ward) p.specular()).value(N, wo, wi);
    }

    private static MutableVec3 direction(double thetaDeg, double phiDeg) {
        double t = Math.toRadians(thetaDeg);
        double p = Math.toRadians(phiDeg);
        return new MutableVec3().set(Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t));
    }

    @ParameterizedTest
    @EnumSource(FittedPreset.class)
    void nonNegativeAndReciprocal(FittedPreset p) {
        SplittableRandom r = new SplittableRandom(p.ordinal());
        for (int i = 0; i < 20_000; i++) {
            MutableVec3 a = direction(r.nextDouble(0, 90), r.nextDouble(0, 360));
            MutableVec3 b = direction(r.nextDouble(0, 90), r.nextDouble(0, 360));
            double ab = lobe(p, a, b);
            double ba = lobe(p, b, a);
            assertTrue(ab >= 0, "negative");
            assertEquals(ab, ba, 1e-12 * Math.max(1, ab), "reciprocity");
        }
        // below the surface nothing is reflected
        assertEquals(0, lobe(p, direction(30, 0), direction(100, 180)));
    }

    @ParameterizedTest
    @EnumSource(FittedPreset.class)
    void finiteAtGrazingAngles(FittedPreset p) {
        for (double eps : new double[] {1e-3, 1e-6, 1e-9, 1e-12}) {
            for (double phi : new double[] {0, 90, 180}) {
                double v = lobe(p, direction(90 - eps, 0), direction(90 - eps, phi));
                assertTrue(Double.isFinite(v) && v >= 0, p + " at " + eps + ": " + v);
            }
            // in the mirror configuration (h = n) f cos(theta_i) has a closed form: Ward 1 / (4 pi a^2),
            // bounded; Ward-Duer 1 / (4 pi a^2 cos(theta)), growing as its normalisation does;
            // Blinn-Phong (e + 2) / (2 pi) cos(theta)
            double angle = Math.toRadians(eps);
            MutableVec3 wo = new MutableVec3().set(Math.cos(angle), 0, Math.sin(angle));
            MutableVec3 wi = new MutableVec3().set(-Math.cos(angle), 0, Math.sin(angle));
            double a2 = p.roughness() * p.roughness();
            double expected = switch (p.model()) {
                case WARD -> 1 / (4 * Math.PI * a2);
                case WARD_DUER -> 1 / (4 * Math.PI * a2 * Math.sin(angle));
                case BLINN_PHONG -> (p.roughness() + 2) / (2 * Math.PI) * Math.sin(angle);
            };
            assertEquals(expected, lobe(p, wo, wi) * Math.sin(angle), 1e-9 * expected, p + " at " + eps);
        }
        assertEquals(0, lobe(p, new MutableVec3().set(1, 0, 0), direction(45, 180)), "exactly grazing gives 0");
    }

    /**
     * Directional albedo, the integral of f cos(theta_i) over the hemisphere, by quadrature in the
     * half-vector domain (d omega_i = 4 (wo . h) d omega_h), with theta_h = atan(w s) so the steps
     * follow the lobe's width w whatever the exponent; the diffuse part adds rho_d exactly.
     */
    @ParameterizedTest
    @EnumSource(FittedPreset.class)
    void reflectsLessThanItReceives(FittedPreset p) {
        double width = p.model() == FittedPreset.Model.BLINN_PHONG ? Math.sqrt(2 / (p.roughness() + 2)) : p.roughness();
        for (double thetaO : new double[] {0, 30, 60, 80}) {
            MutableVec3 wo = direction(thetaO, 0);
            double sMax = Math.tan(Math.PI / 2 - 1e-9) / width;
            int steps = 4000;
            int phis = 720;
            double lobeAlbedo = 0;
            for (int i = 0; i < steps; i++) {
                // s on a geometric-ish grid: dense near the peak, reaching the horizon
                double u0 = (double) i / steps;
                double u1 = (double) (i + 1) / steps;
                double s0 = Math.expm1(u0 * Math.log1p(sMax));
                double s1 = Math.expm1(u1 * Math.log1p(sMax));
                double theta0 = Math.atan(width * s0);
                double theta1 = Math.atan(width * s1);
                double thetaH = 0.5 * (theta0 + theta1);
                double dTheta = theta1 - theta0;
                for (int j = 0; j < phis; j++) {
                    double phiH = (j + 0.5) * 2 * Math.PI / phis;
                    MutableVec3 h = new MutableVec3().set(Math.sin(thetaH) * Math.cos(phiH), Math.sin(thetaH) * Math.sin(phiH), Math.cos(thetaH));
                    double oh = wo.dot(h);
                    if (oh <= 0) {
                        continue;
                    }
                    MutableVec3 wi = new MutableVec3().set(2 * oh * h.x - wo.x, 2 * oh * h.y - wo.y, 2 * oh * h.z - wo.z);
                    if (wi.z <= 0) {
                        continue;
                    }
                    double dOmegaH = Math.sin(thetaH) * dTheta * (2 * Math.PI / phis);
                    lobeAlbedo += lobe(p, wo, wi) * wi.z * 4 * oh * dOmegaH;
                }
            }
            double maxRhoS = p.rhoS().max();
            double maxRhoD = p.rhoD().max();
            double total = maxRhoD + maxRhoS * lobeAlbedo;
            assertTrue(total < 1, p + " at theta_o " + thetaO + ": albedo " + total);
            assertTrue(lobeAlbedo > 0.05, p + " the lobe should reflect something: " + lobeAlbedo);
        }
    }
}

package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.PropertyCheck.forAll;

import org.junit.jupiter.api.Test;

/**
 * Fresnel reflectance against the transmittance computed independently from the amplitude
 * transmission coefficients (Hecht, Optics, section 4.6.2): t_s = 2 n_i cos_i / (n_i cos_i + n_t cos_t),
 * t_p = 2 n_i cos_i / (n_t cos_i + n_i cos_t), T = (n_t cos_t) / (n_i cos_i) t^2, with cos_t from
 * Snell's law computed here. Energy is conserved per polarisation, R + T = 1; R lies in [0, 1]; past
 * the critical angle R = 1; and the reverse path sees the same reflectance, R(i; n_i, n_t) =
 * R(t; n_t, n_i). Indices from 1 to 3 on either side, any angle of incidence.
 */
class FresnelPropertiesTest {
    private static final int TRIES = 1000;
    /** A dozen operations on numbers of order 1: a few ulps, well inside 1e-12. */
    private static final double TOLERANCE = 1e-12;

    @Test
    void reflectancePlusTransmittanceIsOne() {
        forAll("R + T = 1 for s and p", TRIES, random -> {
            double etaI = random.nextDouble(1, 3);
            double etaT = random.nextDouble(1, 3);
            double cosI = random.nextInt(10) == 0 ? 1 : random.nextDouble();
            double sinT = etaI / etaT * Math.sqrt(1 - cosI * cosI);
            String what = "cos_i " + cosI + ", n_i " + etaI + ", n_t " + etaT;
            double r = Fresnel.dielectric(cosI, etaI, etaT);
            assertTrue(r >= 0 && r <= 1, what + ": R = " + r);
            if (sinT >= 1) {
                assertEquals(1, r, 0, what + ": total internal reflection");
                return;
            }
            double cosT = Math.sqrt(1 - sinT * sinT);
            double ts = 2 * etaI * cosI / (etaI * cosI + etaT * cosT);
            double tp = 2 * etaI * cosI / (etaT * cosI + etaI * cosT);
            double flux = etaT * cosT / (etaI * cosI);
            double s = Fresnel.perpendicular(cosI, etaI, etaT);
            double p = Fresnel.parallel(cosI, etaI, etaT);
            assertEquals(1, s + flux * ts * ts, TOLERANCE, what + ": s");
            assertEquals(1, p + flux * tp * tp, TOLERANCE, what + ": p");
            assertEquals(0.5 * (s + p), r, TOLERANCE, what + ": unpolarised");
            // the reverse path, from the transmitted side at the refraction angle: Fresnel recovers
            // cos_i from cos_t by Snell's law, which near grazing loses about 1 / cos_i^2 ulps
            assertEquals(r, Fresnel.dielectric(cosT, etaT, etaI), TOLERANCE * (1 + 1 / (cosI * cosI)), what + ": reverse path");
        });
    }
}

package raytracer.btdf;

import raytracer.core.BTDF;
import raytracer.core.ShadeRec;
import raytracer.math.Fresnel;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * Refraction by Snell's law at a smooth boundary between the outside (index 1) and a medium of
 * index {@code ior} (Suffern, sections 27.2 and 28.2; pbrt-v3 section 8.2.3), carrying the
 * fraction 1 - R that the exact Fresnel reflectance R leaves to transmission (the book's
 * FresnelTransmitter). Which way the light crosses follows from {@code sr.frontFace}; the normal
 * always faces {@code wo}. Radiance is not scaled by (eta_t / eta_i)^2: see Dielectric.
 */
public final class PerfectTransmitter implements BTDF {
    private final double ior;

    public PerfectTransmitter(double ior) {
        if (!(ior > 0) || !Double.isFinite(ior)) {
            throw new IllegalArgumentException("index of refraction must be positive, got " + ior);
        }
        this.ior = ior;
    }

    /** The ratio eta_i / eta_t for light arriving on the side {@code wo} is on. */
    public double relativeEta(ShadeRec sr) {
        return sr.frontFace ? 1 / ior : ior;
    }

    /** Zero: a delta is sampled, never evaluated. */
    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wt, MutableRgb out) {
        out.setBlack();
    }

    /**
     * Snell's law, sin(theta_t) = eta sin(theta_i) with eta = {@link #relativeEta}:
     * wt = -eta wo + (eta cos(theta_i) - cos(theta_t)) n, weight 1 - R(cos(theta_i)) in every
     * channel; false past the critical angle, where sin(theta_t) would exceed 1.
     */
    @Override
    public boolean sampleF(ShadeRec sr, MutableVec3 wo, MutableVec3 wt, MutableRgb weight) {
        MutableVec3 n = sr.normal;
        double eta = relativeEta(sr);
        double cosI = n.dot(wo);
        double sin2T = eta * eta * Math.max(0, 1 - cosI * cosI);
        if (sin2T >= 1) {
            weight.setBlack();
            return false;
        }
        double cosT = Math.sqrt(1 - sin2T);
        double k = eta * cosI - cosT;
        wt.set(-eta * wo.x + k * n.x, -eta * wo.y + k * n.y, -eta * wo.z + k * n.z);
        double t = 1 - Fresnel.dielectric(cosI, 1, 1 / eta);
        weight.set(t, t, t);
        return true;
    }

    /** Zero, as a perfect transmitter has no diffuse part for ambient light to cross. */
    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        out.setBlack();
    }

    public double ior() {
        return ior;
    }
}

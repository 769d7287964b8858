package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The normalised Blinn-Phong lobe around the half vector, as Ngan et al. fit it (docs/brdf-params.md):
 * f_s = rho_s (n + 2) / (2 pi) cos^n(theta_h). Zero when either direction is below the surface.
 */
public final class BlinnPhong implements BRDF {
    private final RGBColor rhoS;
    private final double exponent;

    public BlinnPhong(RGBColor rhoS, double exponent) {
        if (!(exponent >= 0)) {
            throw new IllegalArgumentException("Blinn-Phong exponent must be 0 or more, got " + exponent);
        }
        this.rhoS = rhoS;
        this.exponent = exponent;
    }

    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        out.set(rhoS).scale(value(sr.normal, wo, wi));
    }

    double value(MutableVec3 n, MutableVec3 wo, MutableVec3 wi) {
        if (n.dot(wi) <= 0 || n.dot(wo) <= 0) {
            return 0;
        }
        double cosH = HalfVector.cosThetaH(n, wi, wo);
        return cosH <= 0 ? 0 : (exponent + 2) / (2 * Math.PI) * Math.pow(cosH, exponent);
    }

    /** Zero when rho_s is black: f is rho_s times a power of a cosine, at most (e + 2) / (2 pi). */
    @Override
    public boolean isBlack() {
        return rhoS.isBlack();
    }

    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        out.setBlack();
    }
}

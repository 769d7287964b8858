package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The isotropic Ward lobe (Ward 1992), in the form fitted by Ngan, Durand and Matusik 2005
 * (docs/brdf-params.md): f_s = rho_s exp(-tan^2 theta_h / alpha^2) / (4 pi alpha^2 N), with
 * N = sqrt(cos theta_i cos theta_o) (Ward) or N = cos theta_i cos theta_o (Dür's normalisation,
 * "Ward-Duer"). Zero when either direction is below the surface.
 */
public final class Ward implements BRDF {
    private final RGBColor rhoS;
    private final double alpha;
    private final boolean duer;

    public Ward(RGBColor rhoS, double alpha, boolean duer) {
        if (!(alpha > 0)) {
            throw new IllegalArgumentException("Ward roughness alpha must be positive, got " + alpha);
        }
        this.rhoS = rhoS;
        this.alpha = alpha;
        this.duer = duer;
    }

    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        out.set(rhoS).scale(value(sr.normal, wo, wi));
    }

    /** The scalar part of f_s for unit vectors (rho_s aside). */
    double value(MutableVec3 n, MutableVec3 wo, MutableVec3 wi) {
        double cosI = n.dot(wi);
        double cosO = n.dot(wo);
        double cosH = HalfVector.cosThetaH(n, wi, wo);
        if (cosI <= 0 || cosO <= 0 || cosH <= 0) {
            return 0;
        }
        double cos2 = cosH * cosH;
        double tan2 = (1 - cos2) / cos2;
        double normalisation = duer ? cosI * cosO : Math.sqrt(cosI * cosO);
        return Math.exp(-tan2 / (alpha * alpha)) / (4 * Math.PI * alpha * alpha * normalisation);
    }

    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        out.setBlack();
    }
}

package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.SampleMapping;
import raytracer.math.MutableVec3;

/**
 * Phong's specular lobe (report eq. 1, Suffern section 15.3): f = ks cs cos^e(alpha), alpha between
 * wo and the mirror direction r of wi. The report's form is unnormalised; the normalised modified
 * Phong lobe ks (e + 2) / (2 pi) cos^e(alpha) conserves energy and is offered as an option.
 * Direct light evaluates {@link #f}; glossy reflection traces rays drawn by {@link #sampleF}.
 */
public final class GlossySpecular implements BRDF {
    private final RGBColor cs;
    private final double exp;
    private final double scale;

    public GlossySpecular(double ks, RGBColor cs, double exp, boolean normalized) {
        this.cs = cs;
        this.exp = exp;
        this.scale = normalized ? ks * (exp + 2) / (2 * Math.PI) : ks;
    }

    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        out.set(cs).scale(scale * cosPower(sr, wo, wi));
    }

    /**
     * cos^e(alpha), alpha between wo and the mirror direction r of wi, or 0 past 90 degrees: the
     * factor {@link #f} and {@link #pdf} share (alpha is also the angle between wi and the mirror
     * direction of wo), so that one power serves both.
     */
    public double cosPower(ShadeRec sr, MutableVec3 wo, MutableVec3 wi) {
        MutableVec3 n = sr.normal;
        double nDotWi = n.dot(wi);
        // r = -wi + 2 (n . wi) n
        double rx = -wi.x + 2 * nDotWi * n.x;
        double ry = -wi.y + 2 * nDotWi * n.y;
        double rz = -wi.z + 2 * nDotWi * n.z;
        double rDotWo = rx * wo.x + ry * wo.y + rz * wo.z;
        return rDotWo > 0 ? Math.pow(rDotWo, exp) : 0;
    }

    /**
     * Suffern's sample_f (chapter 25): picks wi around the mirror direction r of wo with density
     * (e + 1) / (2 pi) cos^e(alpha) (phi = 2 pi u, cos(alpha) = (1 - v)^(1/(e+1)); the report's section 2.1)
     * and writes the weight f cos(theta_i) / pdf = ks cs 2 pi / (e + 1) cos(theta_i) for the
     * report's lobe (cos^e cancels; times (e + 2) / (2 pi) when normalised). A direction below the
     * surface gives false and a black weight, and still counts as a sample (docs/brdf-params.md).
     */
    @Override
    public boolean sampleF(ShadeRec sr, MutableVec3 wo, double u, double v, MutableVec3 wi, MutableRgb weight) {
        MutableVec3 n = sr.normal;
        double nDotWo = n.dot(wo);
        // r = -wo + 2 (n . wo) n
        double rx = -wo.x + 2 * nDotWo * n.x;
        double ry = -wo.y + 2 * nDotWo * n.y;
        double rz = -wo.z + 2 * nDotWo * n.z;
        SampleMapping.toHemisphere(u, v, exp, rx, ry, rz, wi);
        double cosI = n.dot(wi);
        if (cosI <= 0) {
            weight.setBlack();
            return false;
        }
        // f / pdf = scale cos^e / ((e + 1) / (2 pi) cos^e)
        weight.set(cs).scale(scale * 2 * Math.PI / (exp + 1) * cosI);
        return true;
    }

    /** The density of {@link #sampleF} for wi, over solid angle: (e + 1) / (2 pi) cos^e(alpha). */
    @Override
    public double pdf(ShadeRec sr, MutableVec3 wo, MutableVec3 wi) {
        MutableVec3 n = sr.normal;
        double nDotWo = n.dot(wo);
        double rDotWi = (-wo.x + 2 * nDotWo * n.x) * wi.x + (-wo.y + 2 * nDotWo * n.y) * wi.y + (-wo.z + 2 * nDotWo * n.z) * wi.z;
        return SampleMapping.hemispherePdf(rDotWi, exp);
    }

    /** Zero when ks or the colour is 0: f is then 0 times a power of a cosine, at most 1. */
    @Override
    public boolean isBlack() {
        return scale == 0 || cs.isBlack();
    }

    /** A lobe this narrow has no meaningful ambient response; Suffern returns black too. */
    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        out.setBlack();
    }

    public RGBColor cs() {
        return cs;
    }

    public double exp() {
        return exp;
    }

    /** The factor of cs cos^e(alpha): ks, or ks (e + 2) / (2 pi) for the normalised lobe. */
    public double scale() {
        return scale;
    }
}

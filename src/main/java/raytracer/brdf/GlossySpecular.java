package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/**
 * Phong's specular lobe (report eq. 1, Suffern section 15.3): f = ks cs cos^e(alpha), alpha between
 * wo and the mirror direction r of wi. The report's form is unnormalised; the normalised modified
 * Phong lobe ks (e + 2) / (2 pi) cos^e(alpha) conserves energy and is offered as an option.
 */
public final class GlossySpecular implements BRDF {
    private final double ks;
    private final RGBColor cs;
    private final double exp;
    private final double scale;

    public GlossySpecular(double ks, RGBColor cs, double exp, boolean normalized) {
        this.ks = ks;
        this.cs = cs;
        this.exp = exp;
        this.scale = normalized ? ks * (exp + 2) / (2 * Math.PI) : ks;
    }

    @Override
    public void f(ShadeRec sr, Vec3 wo, Vec3 wi, Rgb out) {
        Vec3 n = sr.normal;
        double nDotWi = n.dot(wi);
        // r = -wi + 2 (n . wi) n
        double rx = -wi.x + 2 * nDotWi * n.x;
        double ry = -wi.y + 2 * nDotWi * n.y;
        double rz = -wi.z + 2 * nDotWi * n.z;
        double rDotWo = rx * wo.x + ry * wo.y + rz * wo.z;
        if (rDotWo > 0) {
            out.set(cs).scale(scale * Math.pow(rDotWo, exp));
        } else {
            out.setBlack();
        }
    }

    /** A lobe this narrow has no meaningful ambient response; Suffern returns black too. */
    @Override
    public void rho(ShadeRec sr, Vec3 wo, Rgb out) {
        out.setBlack();
    }

    public double ks() {
        return ks;
    }
}

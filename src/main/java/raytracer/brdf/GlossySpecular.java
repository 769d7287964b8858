package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;
import raytracer.math.SampleMapping;
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

    /**
     * Samples wi around the mirror direction r of wo with density (e + 1) / (2 pi) cos^e(alpha)
     * (SPEC section 2: phi = 2 pi u, cos(alpha) = (1 - v)^(1/(e+1))), writes it into {@code wi} and
     * returns f cos(theta_i) / pdf without the colour cs: ks 2 pi / (e + 1) cos(theta_i) for the
     * report's lobe. A direction below the surface returns 0 and still counts as a sample, which
     * keeps the estimate of the truncated integral unbiased (brdf-params.md).
     */
    public double sample(ShadeRec sr, Vec3 wo, double u, double v, Vec3 wi) {
        Vec3 n = sr.normal;
        double nDotWo = n.dot(wo);
        double rx = -wo.x + 2 * nDotWo * n.x;
        double ry = -wo.y + 2 * nDotWo * n.y;
        double rz = -wo.z + 2 * nDotWo * n.z;
        // an orthonormal frame (a, b, r) around the mirror direction
        double hx = Math.abs(rx) > 0.9 ? 0 : 1;
        double hy = Math.abs(rx) > 0.9 ? 1 : 0;
        double ax = hy * rz;
        double ay = -hx * rz;
        double az = hx * ry - hy * rx;
        double len = Math.sqrt(ax * ax + ay * ay + az * az);
        ax /= len;
        ay /= len;
        az /= len;
        double bx = ry * az - rz * ay;
        double by = rz * ax - rx * az;
        double bz = rx * ay - ry * ax;
        SampleMapping.toHemisphere(u, v, exp, wi);
        double lx = wi.x;
        double ly = wi.y;
        double lz = wi.z;
        wi.set(lx * ax + ly * bx + lz * rx, lx * ay + ly * by + lz * ry, lx * az + ly * bz + lz * rz);
        double cosI = n.dot(wi);
        if (cosI <= 0) {
            return 0;
        }
        // f / pdf = scale cos^e / ((e + 1) / (2 pi) cos^e)
        return scale * 2 * Math.PI / (exp + 1) * cosI;
    }

    /** The density of {@link #sample} for wi, over solid angle. */
    public double pdf(ShadeRec sr, Vec3 wo, Vec3 wi) {
        Vec3 n = sr.normal;
        double nDotWo = n.dot(wo);
        double rDotWi = (-wo.x + 2 * nDotWo * n.x) * wi.x + (-wo.y + 2 * nDotWo * n.y) * wi.y + (-wo.z + 2 * nDotWo * n.z) * wi.z;
        return SampleMapping.hemispherePdf(rDotWi, exp);
    }

    public RGBColor color() {
        return cs;
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

package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * Reference solution of exercise 7 (docs/teaching.md): the Cook-Torrance microfacet BRDF
 * f = D G F / (4 cos(theta_o) cos(theta_i)) (Cook and Torrance 1982), with the GGX distribution
 * D(h) = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2) and Smith's separable masking
 * G1(v) = 2 (n.v) / ((n.v) + sqrt(alpha^2 + (1 - alpha^2) (n.v)^2)) (Walter et al., EGSR 2007,
 * eqs. 33 and 34), and Schlick's Fresnel F = f0 + (1 - f0) (1 - wi.h)^5. It samples half vectors
 * by D(h) (n.h), which makes wi's density D (n.h) / (4 wo.h) (Walter et al., eqs. 35 and 38).
 */
public final class CookTorrance implements BRDF {
    private final RGBColor f0;
    private final double alpha2;

    public CookTorrance(RGBColor f0, double alpha) {
        if (!(alpha > 0) || !(alpha <= 1)) {
            throw new IllegalArgumentException("roughness alpha must be in (0, 1], got " + alpha);
        }
        this.f0 = f0;
        this.alpha2 = alpha * alpha;
    }

    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        MutableVec3 n = sr.normal;
        double cosO = n.dot(wo);
        double cosI = n.dot(wi);
        double hx = wo.x + wi.x;
        double hy = wo.y + wi.y;
        double hz = wo.z + wi.z;
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (!(cosO > 0 && cosI > 0 && len > 0)) {
            out.setBlack();
            return;
        }
        double cosH = n.dot(hx, hy, hz) / len;
        double cosD = wi.dot(hx, hy, hz) / len;
        double scale = d(cosH) * g1(cosO) * g1(cosI) / (4 * cosO * cosI);
        schlick(cosD, out).scale(scale);
    }

    @Override
    public boolean sampleF(ShadeRec sr, MutableVec3 wo, double u, double v, MutableVec3 wi, MutableRgb weight) {
        MutableVec3 n = sr.normal;
        double cosO = n.dot(wo);
        // a half vector with density D(h) (n.h): tan^2(theta_h) = alpha^2 u / (1 - u)
        double cos2 = (1 - u) / (1 + (alpha2 - 1) * u);
        double cosH = Math.sqrt(cos2);
        double sinH = Math.sqrt(Math.max(0, 1 - cos2));
        double phi = 2 * Math.PI * v;
        // an orthonormal frame (s, t, n) (Duff et al., JCGT 2017)
        double sign = Math.copySign(1, n.z);
        double k = -1 / (sign + n.z);
        double b = n.x * n.y * k;
        double sx = 1 + sign * n.x * n.x * k;
        double sy = sign * b;
        double sz = -sign * n.x;
        double tx = b;
        double ty = sign + n.y * n.y * k;
        double tz = -n.y;
        double a = sinH * Math.cos(phi);
        double c = sinH * Math.sin(phi);
        double hx = a * sx + c * tx + cosH * n.x;
        double hy = a * sy + c * ty + cosH * n.y;
        double hz = a * sz + c * tz + cosH * n.z;
        // wi = the mirror image of wo about h
        double oh = wo.dot(hx, hy, hz);
        wi.set(2 * oh * hx - wo.x, 2 * oh * hy - wo.y, 2 * oh * hz - wo.z);
        double cosI = n.dot(wi);
        if (!(cosO > 0 && cosI > 0 && oh > 0)) {
            weight.setBlack();
            return false;
        }
        // f cos(theta_i) / pdf = F G (wo.h) / (cos(theta_o) (n.h)): D cancels
        schlick(oh, weight).scale(g1(cosO) * g1(cosI) * oh / (cosO * cosH));
        return true;
    }

    @Override
    public double pdf(ShadeRec sr, MutableVec3 wo, MutableVec3 wi) {
        MutableVec3 n = sr.normal;
        double hx = wo.x + wi.x;
        double hy = wo.y + wi.y;
        double hz = wo.z + wi.z;
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        double oh = wo.dot(hx, hy, hz) / len;
        if (!(n.dot(wo) > 0 && n.dot(wi) > 0 && oh > 0)) {
            return 0;
        }
        double cosH = n.dot(hx, hy, hz) / len;
        return d(cosH) * cosH / (4 * oh);
    }

    /** A glossy lobe answers no ambient light, as Suffern's GlossySpecular does. */
    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        out.setBlack();
    }

    private double d(double cosH) {
        double x = cosH * cosH * (alpha2 - 1) + 1;
        return alpha2 / (Math.PI * x * x);
    }

    private double g1(double cos) {
        return 2 * cos / (cos + Math.sqrt(alpha2 + (1 - alpha2) * cos * cos));
    }

    private MutableRgb schlick(double cosD, MutableRgb out) {
        double m = Math.pow(1 - cosD, 5);
        return out.set(f0.r() + (1 - f0.r()) * m, f0.g() + (1 - f0.g()) * m, f0.b() + (1 - f0.b()) * m);
    }
}

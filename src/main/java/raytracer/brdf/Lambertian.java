package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * Perfect diffuse reflection: f = kd cd / pi, rho = kd cd (Suffern, section 13.9); with a texture,
 * cd is looked up at the hit (the book's SV_Lambertian), and only then.
 */
public final class Lambertian implements BRDF {
    private final double kd;
    /** kd / pi, divided once here rather than at every light sample (the same double). */
    private final double kdOverPi;
    private final RGBColor cd;
    private final Texture texture;

    public Lambertian(double kd, RGBColor cd) {
        this.kd = kd;
        this.kdOverPi = kd / Math.PI;
        this.cd = cd;
        this.texture = null;
    }

    public Lambertian(double kd, Texture texture) {
        this.kd = kd;
        this.kdOverPi = kd / Math.PI;
        this.cd = null;
        this.texture = texture;
    }

    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        color(sr, out).scale(kdOverPi);
    }

    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        color(sr, out).scale(kd);
    }

    /** Zero when kd is 0 or the colour is black; a texture's colours are not known unless constant. */
    @Override
    public boolean isBlack() {
        RGBColor c = texture == null ? cd : texture.constantColor();
        return kd == 0 || c != null && c.isBlack();
    }

    /** A constant texture becomes the plain colour it always gives, which needs no lookup. */
    @Override
    public BRDF simplified() {
        RGBColor constant = texture == null ? null : texture.constantColor();
        return constant == null ? this : new Lambertian(kd, constant);
    }

    private MutableRgb color(ShadeRec sr, MutableRgb out) {
        if (texture == null) {
            return out.set(cd);
        }
        texture.getColor(sr, out);
        return out;
    }
}

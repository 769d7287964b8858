package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/**
 * Perfect diffuse reflection: f = kd cd / pi, rho = kd cd (Suffern, section 13.9); with a texture,
 * cd is looked up at the hit (the book's SV_Lambertian), and only then.
 */
public final class Lambertian implements BRDF {
    private final double kd;
    private final RGBColor cd;
    private final Texture texture;

    public Lambertian(double kd, RGBColor cd) {
        this.kd = kd;
        this.cd = cd;
        this.texture = null;
    }

    public Lambertian(double kd, Texture texture) {
        this.kd = kd;
        this.cd = null;
        this.texture = texture;
    }

    @Override
    public void f(ShadeRec sr, Vec3 wo, Vec3 wi, Rgb out) {
        color(sr, out).scale(kd / Math.PI);
    }

    @Override
    public void rho(ShadeRec sr, Vec3 wo, Rgb out) {
        color(sr, out).scale(kd);
    }

    private Rgb color(ShadeRec sr, Rgb out) {
        if (texture == null) {
            return out.set(cd);
        }
        texture.getColor(sr, out);
        return out;
    }
}

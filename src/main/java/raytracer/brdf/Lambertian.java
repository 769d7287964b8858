package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/** Perfect diffuse reflection: f = kd cd / pi, rho = kd cd (Suffern, section 13.9). */
public final class Lambertian implements BRDF {
    private final double kd;
    private final RGBColor cd;

    public Lambertian(double kd, RGBColor cd) {
        this.kd = kd;
        this.cd = cd;
    }

    @Override
    public void f(ShadeRec sr, Vec3 wo, Vec3 wi, Rgb out) {
        out.set(cd).scale(kd / Math.PI);
    }

    @Override
    public void rho(ShadeRec sr, Vec3 wo, Rgb out) {
        out.set(cd).scale(kd);
    }
}

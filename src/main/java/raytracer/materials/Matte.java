package raytracer.materials;

import raytracer.brdf.Lambertian;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;

/** A purely diffuse surface (Suffern, section 14.7): ambient ka cd plus Lambertian kd cd / pi. */
public final class Matte extends Material {
    private final Lambertian ambient;
    private final Lambertian diffuse;

    public Matte(double ka, double kd, RGBColor cd) {
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, null, out);
    }
}

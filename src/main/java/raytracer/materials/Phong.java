package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;

/** Diffuse plus Phong highlights (report eq. 1, Suffern section 15.5). */
public final class Phong extends Material {
    private final Lambertian ambient;
    private final Lambertian diffuse;
    private final GlossySpecular specular;

    public Phong(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, boolean normalized) {
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
        this.specular = new GlossySpecular(ks, cs, exp, normalized);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, specular, out);
    }
}

package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;

/** Diffuse plus Phong highlights (report eq. 1, Suffern section 15.5). */
public final class Phong extends Material {
    private Lambertian ambient;
    private Lambertian diffuse;
    private final double ka;
    private final double kd;
    private final GlossySpecular specular;

    public Phong(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, boolean normalized) {
        this.ka = ka;
        this.kd = kd;
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
        this.specular = new GlossySpecular(ks, cs, exp, normalized);
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        this.ambient = new Lambertian(ka, texture);
        this.diffuse = new Lambertian(kd, texture);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, specular, out);
    }
}

package raytracer.materials;

import raytracer.brdf.Lambertian;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;

/** A purely diffuse surface (Suffern, section 14.7): ambient ka cd plus Lambertian kd cd / pi. */
public final class Matte extends Material {
    private Lambertian ambient;
    private Lambertian diffuse;
    private final double ka;
    private final double kd;

    public Matte(double ka, double kd, RGBColor cd) {
        this.ka = ka;
        this.kd = kd;
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        this.ambient = new Lambertian(ka, texture);
        this.diffuse = new Lambertian(kd, texture);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, null, out);
    }
}

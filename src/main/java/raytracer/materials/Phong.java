package raytracer.materials;

import java.util.ArrayList;
import java.util.List;
import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Texture;
import raytracer.core.World;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/** Diffuse plus Phong highlights (report eq. 1, Suffern section 15.5; area lights: chapter 18). */
public final class Phong extends Material {
    /** Whether a texture that reads u, v replaced the plain diffuse colour. */
    private boolean textured;
    private final double ka;
    private final double kd;
    private RGBColor cd;
    private final GlossySpecular specular;
    private DirectLighting lighting;

    public Phong(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, boolean normalized) {
        this.ka = ka;
        this.kd = kd;
        this.cd = cd;
        this.specular = new GlossySpecular(ks, cs, exp, normalized);
        this.lighting = new DirectLighting(new Lambertian(ka, cd), new Lambertian(kd, cd), specular);
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        textured = texture.usesTextureCoordinates();
        this.cd = null;
        this.lighting = new DirectLighting(new Lambertian(ka, texture), new Lambertian(kd, texture), specular);
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        lighting.shade(sr, out);
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        lighting.areaLightShade(sr, out);
    }

    @Override
    public boolean usesTextureCoordinates() {
        return textured;
    }

    @Override
    public List<Skip> simplify(World world, boolean mayDropRays) {
        List<Skip> skips = new ArrayList<>();
        lighting = lighting.simplified(world, name(), skips);
        return skips;
    }

    public double ka() {
        return ka;
    }

    public double kd() {
        return kd;
    }

    /** The diffuse colour, or null when a texture replaced it. */
    public RGBColor cd() {
        return cd;
    }

    public GlossySpecular specular() {
        return specular;
    }
}

package raytracer.materials;

import java.util.ArrayList;
import java.util.List;
import raytracer.brdf.Lambertian;
import raytracer.core.BRDF;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingNeeds;
import raytracer.core.Skip;
import raytracer.core.Texture;
import raytracer.core.World;
import raytracer.math.MutableRgb;
import raytracer.math.RGBColor;

/**
 * A material lit by the scene's lights: the book's Matte and Phong, whose direct light is an
 * ambient term ka cd, a Lambertian kd cd / pi and an optional specular lobe ({@link DirectLighting}),
 * and the materials that add rays to Phong's light (Reflective, GlossyReflector and the glasses,
 * which extend Phong as in the book) or fit its lobe to measurements (Fitted). What the scene
 * analysis leaves out of the lighting is done once, here, for all of them ({@link #simplify}).
 */
abstract class LitMaterial extends Material {
    private final double ka;
    private final double kd;
    /** Null when a texture replaced the plain diffuse colour. */
    private RGBColor cd;
    /** Whether a texture that reads u, v replaced the plain diffuse colour. */
    private boolean textured;
    /** The book's lighting, as made; {@link #lighting} is it or what the analysis made of it. */
    private DirectLighting direct;
    private Lighting lighting;

    /** Ambient ka cd, diffuse kd cd / pi, and {@code specular} (null for none) meeting cos(theta_i) as {@code terms} say. */
    LitMaterial(double ka, double kd, RGBColor cd, BRDF specular, LightingTerms terms, GlossyLightMis mis) {
        this.ka = ka;
        this.kd = kd;
        this.cd = cd;
        this.direct = new DirectLighting(new Lambertian(ka, cd), new Lambertian(kd, cd), specular, terms, mis);
        this.lighting = direct;
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        textured = texture.usesTextureCoordinates();
        cd = null;
        direct = new DirectLighting(new Lambertian(ka, texture), new Lambertian(kd, texture), direct.specular, direct.terms,
                                    direct.mis);
        lighting = direct;
    }

    /** Suffern's shade: the direct light of each light from its one direction, then the material's own rays. */
    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        lighting.shade(sr, out);
        traceRays(sr, out);
    }

    /** Suffern's area_light_shade: the direct light of each light's samples, then the material's own rays. */
    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        lighting.areaLightShade(sr, out);
        traceRays(sr, out);
    }

    /**
     * Adds into {@code out}, after the direct light (which set sr.wo), the radiance of the rays
     * the material traces: a mirror's (Reflective), glossy rays (GlossyReflector), glass's. The
     * book's Matte and Phong trace none.
     */
    void traceRays(ShadeRec sr, MutableRgb out) {
    }

    /** The lighting in use: the book's, or what the analysis left of it. */
    final Lighting lighting() {
        return lighting;
    }

    @Override
    public ShadingNeeds needs() {
        return ShadingNeeds.directLight(textured);
    }

    /** Whether a texture that reads u, v replaced the plain diffuse colour. */
    final boolean textured() {
        return textured;
    }

    /** The lighting without the terms that are zero at every hit of {@code world} ({@link SimplifiedLighting}); once. */
    @Override
    public List<Skip> simplify(World world, boolean mayDropRays) {
        List<Skip> skips = new ArrayList<>();
        if (lighting == direct) {
            lighting = SimplifiedLighting.of(direct, world, name(), skips);
        }
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
}

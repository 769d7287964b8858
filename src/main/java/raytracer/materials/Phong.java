package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.core.Background;
import raytracer.math.RGBColor;

/**
 * Diffuse plus Phong highlights (report eq. 1, Suffern section 15.5; area lights: chapter 18):
 * ambient ka cd, Lambertian kd cd / pi and the glossy lobe ks cs cos^e(alpha). Reflective,
 * GlossyReflector and the glasses extend it, as in the book.
 */
public class Phong extends LitMaterial {
    private final GlossySpecular specular;
    /** Seen by the rays a subclass traces that escape, instead of the scene's background; null: the scene's. */
    private Background reflectionMap;

    public Phong(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, boolean normalized) {
        this(ka, kd, cd, new GlossySpecular(ks, cs, exp, normalized), null);
    }

    /** With a lobe of its own, weighed against glossy rays by {@code mis} (null: not). */
    Phong(double ka, double kd, RGBColor cd, GlossySpecular specular, GlossyLightMis mis) {
        super(ka, kd, cd, specular, LightingTerms.PHYSICAL, mis);
        this.specular = specular;
    }

    public final GlossySpecular specular() {
        return specular;
    }

    /**
     * Gives this object its own environment for the rays it traces (report section 1: a mirror's,
     * glossy or glass rays; plain Phong traces none); null: the scene's.
     */
    public final void setReflectionMap(Background reflectionMap) {
        this.reflectionMap = reflectionMap;
    }

    /** The object's own environment for the rays it traces, or null for the scene's. */
    public final Background reflectionMap() {
        return reflectionMap;
    }
}

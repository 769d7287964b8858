package raytracer.materials;

import raytracer.math.RGBColor;

/** A purely diffuse surface (Suffern, section 14.7; area lights: chapter 18): ambient ka cd plus Lambertian kd cd / pi. */
public final class Matte extends LitMaterial {
    public Matte(double ka, double kd, RGBColor cd) {
        super(ka, kd, cd, null, LightingTerms.PHYSICAL, null);
    }
}

package raytracer.materials;

import raytracer.brdf.FittedPreset;
import raytracer.core.BRDF;
import raytracer.math.RGBColor;

/**
 * A measured material as a fitted model (report section 2.2, figure 2): Lambertian rho_d / pi plus
 * a Ward, Ward-Duer or Blinn-Phong lobe, lit by the scene's lights (area lights: Suffern, chapter
 * 18), with an ambient term ka rho_d. {@code seedCompatible} reproduces the report's own shading
 * (no 1/pi, no cos on the lobe) so that figure 2's brightness can be matched.
 */
public final class Fitted extends LitMaterial {
    public Fitted(RGBColor rhoD, BRDF specular, double ka, boolean seedCompatible) {
        super(ka, 1, rhoD, specular, seedCompatible ? LightingTerms.REPORT : LightingTerms.PHYSICAL, null);
    }

    public static Fitted of(FittedPreset preset, double ka, boolean seedCompatible) {
        return new Fitted(preset.rhoD(), preset.specular(), ka, seedCompatible);
    }
}

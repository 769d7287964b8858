package raytracer.materials;

import java.util.ArrayList;
import java.util.List;
import raytracer.brdf.FittedPreset;
import raytracer.brdf.Lambertian;
import raytracer.core.BRDF;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.World;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/**
 * A measured material as a fitted model (report section 2.2, figure 2): Lambertian rho_d / pi plus
 * a Ward, Ward-Duer or Blinn-Phong lobe, lit by the scene's lights (area lights: Suffern, chapter
 * 18), with an ambient term ka rho_d.
 * {@code seedCompatible} reproduces the report's own shading (no 1/pi, no cos on the lobe) so that
 * figure 2's brightness can be matched.
 */
public final class Fitted extends Material {
    private DirectLighting lighting;

    public Fitted(RGBColor rhoD, BRDF specular, double ka, boolean seedCompatible) {
        this.lighting = new DirectLighting(new Lambertian(ka, rhoD), new Lambertian(1, rhoD), specular,
                                           seedCompatible ? LightingTerms.REPORT : LightingTerms.PHYSICAL);
    }

    public static Fitted of(FittedPreset preset, double ka, boolean seedCompatible) {
        return new Fitted(preset.rhoD(), preset.specular(), ka, seedCompatible);
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        lighting.shade(sr, out);
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        lighting.areaLightShade(sr, out);
    }

    /** No texture: u, v are never read. */
    @Override
    public boolean usesTextureCoordinates() {
        return false;
    }

    @Override
    public List<Skip> simplify(World world, boolean mayDropRays) {
        List<Skip> skips = new ArrayList<>();
        lighting = lighting.simplified(world, name(), skips);
        return skips;
    }
}

package raytracer.materials;

import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/**
 * A surface that emits radiance ls c from its front side (Suffern, section 18.3): the visible
 * face of an area light. Mirrors and glass that see it reflect its radiance.
 */
public final class Emissive extends Material {
    private final RGBColor radiance;

    public Emissive(double ls, RGBColor color) {
        this.radiance = color.scale(ls);
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        if (sr.frontFace) {
            out.set(radiance);
        } else {
            out.setBlack();
        }
    }

    /** The same: what an emitter shows does not depend on how the lights are sampled. */
    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        shade(sr, out);
    }

    /** No texture: u, v are never read. */
    @Override
    public boolean usesTextureCoordinates() {
        return false;
    }
}

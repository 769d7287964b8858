package raytracer.materials;

import raytracer.core.Light;
import raytracer.core.WorkerScratch;
import raytracer.math.Ray;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingNeeds;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/**
 * A surface that emits radiance ls c from its front side (Suffern, section 18.3): the visible
 * face of an area light. Mirrors and glass that see it reflect its radiance.
 */
public final class Emissive extends Material {
    private final RGBColor radiance;
    /** The area light this surface is the visible face of, or null for an emitter no light samples. */
    private final Light light;

    /** An emitting surface that no light samples (an OBJ material's Ke): only traced rays find it. */
    public Emissive(double ls, RGBColor color) {
        this.radiance = color.scale(ls);
        this.light = null;
    }

    /**
     * The visible face of the area light {@code light}, emitting ls c: the light is told it can be
     * hit, and a ray that hits this surface reports it ({@link WorkerScratch#recordEmitter}), so
     * that a material sampling both the light and its own lobe counts this light once.
     */
    public Emissive(double ls, RGBColor color, Light light) {
        this.radiance = color.scale(ls);
        this.light = light;
        light.showSurface();
    }

    /**
     * Le on the front side. When this is a light's face, the density with which the light's own
     * sampling would choose the ray's direction is recorded ({@link Light#directionPdf}).
     */
    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        if (!sr.frontFace) {
            out.setBlack();
            return;
        }
        out.set(radiance);
        if (light != null) {
            Ray ray = sr.ray;
            double d2 = ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz;
            double cos = Math.abs(sr.geometricNormal.dot(ray.dx, ray.dy, ray.dz)) / Math.sqrt(d2);
            sr.scratch.recordEmitter(sr.depth, light, light.directionPdf(ray.ox, ray.oy, ray.oz, sr.t * Math.sqrt(d2), cos));
        }
    }

    /** The same: what an emitter shows does not depend on how the lights are sampled. */
    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        shade(sr, out);
    }

    /** Direct light alone, and no texture: u, v are never read. */
    @Override
    public ShadingNeeds needs() {
        return ShadingNeeds.directLight(false);
    }
}

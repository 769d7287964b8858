package raytracer.core;

import raytracer.math.Rgb;

/** How a surface answers light (Suffern, chapter 14): {@link #shade} writes outgoing radiance. */
public abstract class Material {

    /** Writes into {@code out} the radiance leaving the completed hit {@code sr} towards the viewer. */
    public abstract void shade(ShadeRec sr, Rgb out);

    /** True when shading this material traces secondary rays (mirror, glass). */
    public boolean tracesSecondaryRays() {
        return false;
    }
}

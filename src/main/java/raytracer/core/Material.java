package raytracer.core;

import raytracer.math.MutableRgb;

/**
 * How a surface answers light (Suffern, chapter 14): the radiance leaving a completed hit towards
 * the viewer, in the book's two forms, one per kind of tracer.
 */
public abstract class Material {

    /**
     * Suffern's shade (chapters 14 and 24), called by the RayCast and Whitted tracers: writes into
     * {@code out} the radiance leaving the hit {@code sr}, each light taken from its one direction.
     */
    public abstract void shade(ShadeRec sr, MutableRgb out);

    /**
     * Suffern's area_light_shade (chapter 18), called by the AreaLighting tracer: as {@link #shade},
     * but each light contributes the average of its samples weighted f L G cos(theta_i) / pdf,
     * which lights with extent need. Secondary rays are traced through the same tracer, so they
     * are shaded this way too.
     */
    public abstract void areaLightShade(ShadeRec sr, MutableRgb out);

    /**
     * Whether shading reads the hit's u, v (through a texture). A material that says false lets
     * the shapes it covers skip computing them; the default says true, to be safe.
     */
    public boolean usesTextureCoordinates() {
        return true;
    }
}

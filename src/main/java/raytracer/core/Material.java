package raytracer.core;

import java.util.List;
import java.util.Locale;
import raytracer.math.MutableRgb;

/**
 * How a surface answers light (Suffern, chapter 14): the radiance leaving a completed hit towards
 * the viewer, in the book's two forms, one per kind of tracer. Before rendering, the scene
 * analysis asks each material what it needs (secondary rays, random numbers) and lets it leave out
 * the terms that are zero at every hit ({@link #simplify}).
 */
public abstract class Material {
    private String name = getClass().getSimpleName().toLowerCase(Locale.ROOT);

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
     * What shading needs, asked by the scene analysis before rendering. This default is direct
     * light alone, reading u, v to be safe: a material that says it does not lets the shapes it
     * covers skip computing them.
     */
    public ShadingNeeds needs() {
        return new ShadingNeeds(true, false, false, false);
    }

    /**
     * Leaves out of the shading, from now on, every term that is zero at every hit of this scene
     * (a ka, kd or ks of 0, an ambient light of zero radiance, a mirror of weight zero) and reads
     * constant textures as plain colours; the image stays the same to the bit, since each left-out
     * term would have added +0. {@code mayDropRays}: rays of weight zero may be left out too,
     * because nothing in the scene draws random numbers that such a ray's subtree would have drawn.
     * Returns what was left out.
     */
    public List<Skip> simplify(World world, boolean mayDropRays) {
        return List.of();
    }

    /** The material's name in the scene file (or its MTL file), for messages. */
    public String name() {
        return name;
    }

    public void setName(String name) {
        this.name = name;
    }
}

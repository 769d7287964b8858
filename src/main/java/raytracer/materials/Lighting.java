package raytracer.materials;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The direct light a lit material reflects, in the book's two forms: {@link DirectLighting} is the
 * book's, {@link SimplifiedLighting} the same with the terms the scene analysis proved zero left
 * out. Both set sr.wo, which the material's rays then use.
 */
interface Lighting {
    /** Suffern's shade: the ambient term plus each light from its one direction, into {@code L}. */
    void shade(ShadeRec sr, MutableRgb L);

    /** Suffern's area_light_shade: the ambient term plus each light's samples averaged, into {@code L}. */
    void areaLightShade(ShadeRec sr, MutableRgb L);

    /**
     * How many samples of {@code light} this hit draws whose specular lobe covers direction
     * {@code wi} (0 when none): a glossy ray that finds the light's surface in direction wi weighs
     * its radiance against them ({@link GlossyLightMis}).
     */
    int lightSamplesToward(ShadeRec sr, Light light, MutableVec3 wi);
}

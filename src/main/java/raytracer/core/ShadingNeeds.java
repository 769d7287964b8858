package raytracer.core;

/**
 * What a material's shading needs, which the scene analysis asks before rendering so that it can
 * leave out what nothing needs ({@link Material#needs}).
 *
 * @param textureCoordinates shading reads the hit's u, v (through a texture); a material that does
 *                           not lets the shapes it covers skip computing them
 * @param rays               shading may trace secondary rays at all, even rays whose radiance it then
 *                           multiplies by 0 (a mirror, a glossy lobe, glass)
 * @param refraction         shading may trace refracted rays of nonzero weight: rays cross its
 *                           surface, so what lies behind it can be seen (glass)
 * @param drawsSamples       shading draws values of its own from the pixel's sample dimensions (the
 *                           directions of glossy rays): leaving its work out would move none of
 *                           them, but a ray of weight 0 left out would drop the draws of its subtree
 */
public record ShadingNeeds(boolean textureCoordinates, boolean rays, boolean refraction, boolean drawsSamples) {

    /** Direct light alone: no rays, no samples of its own. */
    public static ShadingNeeds directLight(boolean textureCoordinates) {
        return new ShadingNeeds(textureCoordinates, false, false, false);
    }
}

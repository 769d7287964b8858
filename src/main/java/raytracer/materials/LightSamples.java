package raytracer.materials;

import raytracer.core.Light;
import raytracer.core.PixelSamples;
import raytracer.core.ShadeRec;

/**
 * Which samples of a light a hit draws (Suffern, chapter 18): one for a light without extent; for
 * a light with extent, the ray tree's count at the hit's depth, as the sampler rounds it, taking
 * the values of the light's own dimension stratified across the pixel's samples
 * ({@link PixelSamples}), so that every value is a function of (seed, pixel, sample, dimension).
 */
final class LightSamples {
    private LightSamples() {
    }

    /** How many samples of {@code light} the hit draws. */
    static int count(ShadeRec sr, Light light) {
        if (!light.hasExtent()) {
            return 1;
        }
        return sr.world.viewPlane().sampler().supportedCount(sr.scratch.policy.lightSamples(sr.depth, light.sampleCount()));
    }

    /**
     * Writes the direction of sample {@code j} into sr.wi and returns the distance to it: the
     * light's one direction, or the point of its surface that the pixel's sample values pick.
     */
    static double sample(ShadeRec sr, Light light, int j) {
        if (!light.hasExtent()) {
            return light.getDirection(sr, sr.wi);
        }
        // the pixel spreads its hits' samples across the light's full count as the sampler rounds it
        int strata = sr.world.viewPlane().sampler().supportedCount(light.sampleCount());
        PixelSamples samples = sr.scratch.samples;
        samples.get2D(sr.depth, PixelSamples.LIGHT + light.number(), j, strata);
        return light.sample(sr, samples.u, samples.v, sr.wi);
    }
}

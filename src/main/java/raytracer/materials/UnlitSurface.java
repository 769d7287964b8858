package raytracer.materials;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.core.Skipped;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The lighting of a surface on which the scene analysis proved every term zero (ka, kd and ks of
 * 0, or an ambient light of zero radiance where ka is not): it reflects no direct light, so no
 * light is evaluated and no shadow ray traced. Black, with sr.wo set as the lighting sets it, and
 * the ambient term and the light samples it did not draw counted ({@link Skipped}).
 */
final class UnlitSurface implements Lighting {
    /** Counts one sample per light, from its direction. */
    @Override
    public void shade(ShadeRec sr, MutableRgb L) {
        if (unlit(sr, L)) {
            sr.scratch.skipped[Skipped.LIGHT_SAMPLES] += sr.world.lights().length;
        }
    }

    /** Counts the samples of each light that could reach the hit. */
    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb L) {
        if (unlit(sr, L)) {
            for (Light light : sr.world.lights()) {
                if (light.mayIlluminate(sr)) {
                    // each sample value is a function of its index: leaving them undrawn moves no later one
                    sr.scratch.skipped[Skipped.LIGHT_SAMPLES] += LightSamples.count(sr, light);
                }
            }
        }
    }

    /** No light sample is drawn: none weighs against a glossy ray. */
    @Override
    public int lightSamplesToward(ShadeRec sr, Light light, MutableVec3 wi) {
        return 0;
    }

    /** Black, sr.wo set; true, with the ambient term counted, when the hit shows direct light. */
    private static boolean unlit(ShadeRec sr, MutableRgb L) {
        sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
        L.setBlack();
        if (!sr.scratch.policy.showsDirect(sr.depth)) {
            return false;
        }
        sr.scratch.skipped[Skipped.AMBIENT_TERMS]++;
        return true;
    }
}

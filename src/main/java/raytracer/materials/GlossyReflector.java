package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.core.Light;
import raytracer.core.PixelSamples;
import raytracer.core.Sampler;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingNeeds;
import raytracer.core.WorkerScratch;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.RGBColor;

/**
 * Glossy Phong (report section 2.1, figure 1b; Suffern, chapter 25): Phong's direct light, and the
 * specular part traced as {@code samples} rays around the mirror direction, drawn by the lobe's
 * sample_f, so that the whole scene is reflected blurred. Every light also gives the specular term
 * directly: point and directional lights, which no ray can hit, alone; an area light through its
 * samples, weighed against the glossy rays that find its visible surface by multiple importance
 * sampling ({@link GlossyLightMis}), so its highlight is there whether or not the light is visible,
 * the rays are traced or the pass shows reflection, and is counted once.
 */
public final class GlossyReflector extends Phong {
    private final GlossyLightMis mis;

    public GlossyReflector(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, int samples,
                           boolean normalized) {
        this(ka, kd, cd, checked(samples), new GlossySpecular(ks, cs, exp, normalized));
    }

    private GlossyReflector(double ka, double kd, RGBColor cd, int samples, GlossySpecular lobe) {
        this(ka, kd, cd, lobe, new GlossyLightMis(lobe, samples));
    }

    private GlossyReflector(double ka, double kd, RGBColor cd, GlossySpecular lobe, GlossyLightMis mis) {
        super(ka, kd, cd, lobe, mis);
        this.mis = mis;
    }

    private static int checked(int samples) {
        if (samples < 1 || samples > Sampler.MAX_SAMPLES) {
            throw new IllegalArgumentException("glossy samples must be 1 to " + Sampler.MAX_SAMPLES + ", got " + samples);
        }
        return samples;
    }

    /**
     * Adds the average over the glossy rays of the radiance each brings back times its weight
     * f cos(theta_i) / pdf (Suffern, chapter 25). The directions come from the glossy dimension of
     * this hit's path, stratified across the pixel's samples, and each ray names its own path. A
     * ray that finds the surface of an area light this hit also samples brings back its radiance
     * weighed against those samples ({@link GlossyLightMis}). The rays see the environment the
     * pass gives reflected rays (magenta for the first hit of the magenta-reflection pass).
     */
    @Override
    void traceRays(ShadeRec sr, MutableRgb out) {
        int next = sr.depth + 1;
        WorkerScratch scratch = sr.scratch;
        if (next > sr.world.viewPlane().maxDepth() || !scratch.policy.showsReflection(sr.depth)) {
            return;
        }
        int n = mis.glossyRays(sr);
        MutableVec3 wi = sr.wi;
        MutableRgb weight = scratch.weight(sr.depth);
        MutableRgb incoming = scratch.color(next);
        double r = 0;
        double g = 0;
        double b = 0;
        for (int i = 0; i < n; i++) {
            scratch.samples.get2D(sr.depth, PixelSamples.GLOSSY, i, n);
            if (!specular().sampleF(sr, sr.wo, scratch.samples.u, scratch.samples.v, wi, weight)
                || !scratch.policy.recordBranchWeight(sr.depth, weight.r / n, weight.g / n, weight.b / n)) {
                continue; // below the surface, or pruned by the cutoff: zero, but it counts in the average
            }
            scratch.clearEmitter(next);
            BranchRay.trace(sr, wi, PixelSamples.GLOSSY_RAY, i, n, scratch, incoming,
                            scratch.policy.reflectedEnvironment(sr.depth, reflectionMap()));
            Light emitter = scratch.emitter(next);
            if (emitter != null) {
                incoming.scale(mis.glossyRayWeight(sr, wi, n, lighting().lightSamplesToward(sr, emitter, wi), scratch.emitterPdf(next)));
            }
            r += incoming.r * weight.r;
            g += incoming.g * weight.g;
            b += incoming.b * weight.b;
        }
        out.r += r / n;
        out.g += g / n;
        out.b += b / n;
    }

    /** Glossy rays are traced even of weight 0 (the lobe's samples are drawn before their weights are known), from the pixel's sample dimensions. */
    @Override
    public ShadingNeeds needs() {
        return new ShadingNeeds(textured(), true, false, true);
    }
}

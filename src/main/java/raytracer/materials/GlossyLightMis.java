package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.core.Light;
import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.RGBColor;

/**
 * How a glossy reflector counts an area light's highlight once though it finds it two ways: the
 * light's own samples, for which the lobe is evaluated like any BRDF ({@link DirectLighting}), and
 * the glossy rays drawn from the lobe, which find the light's surface when it is visible. Each way
 * weighs its samples by the power heuristic (Veach 1995, section 9.2.4, beta = 2):
 * w_s = (n_s p_s)^2 / sum_t (n_t p_t)^2, with n the number of samples each way takes at the hit and
 * p its density for the direction, over solid angle. The weights of a direction sum to 1, so the
 * sum stays unbiased, and each way covers what the other samples poorly: the light's samples a
 * small light under a broad lobe, the glossy rays a sharp lobe under a large light.
 *
 * <p>Where one way cannot find the light at this hit, the other's weight is 1: an invisible light
 * ({@code visible: false}) or a hit whose glossy rays are not traced (max depth, a pass without
 * reflection, a direction whose ray the cutoff would prune) leaves the highlight to the light's
 * samples; a hit that does not sample the light (a pass without direct light) leaves it to the
 * glossy rays.
 */
final class GlossyLightMis {
    private final GlossySpecular lobe;
    /** Glossy rays per hit, before the sampler rounds the count. */
    private final int samples;

    GlossyLightMis(GlossySpecular lobe, int samples) {
        this.lobe = lobe;
        this.samples = samples;
    }

    /** The power heuristic's weight of a sample taken one way, (n p)^2 / ((n p)^2 + (n' p')^2), with np and otherNp the two products. */
    static double powerHeuristic(double np, double otherNp) {
        double a = np * np;
        double b = otherNp * otherNp;
        return a / (a + b);
    }

    /** Glossy rays a hit traces, as the sampler rounds the count. */
    int glossyRays(ShadeRec sr) {
        return sr.world.viewPlane().sampler().supportedCount(samples);
    }

    /**
     * Writes into {@code fs} the lobe's value f for a sample of {@code light} in direction sr.wi,
     * weighed against the glossy rays: the light's sampling drew it {@code lightSamples} times at
     * this hit with solid-angle density {@code lightPdf}. The weight is 1 unless a glossy ray in
     * that direction would be traced and could find the light's surface. One power of the cosine
     * serves f and the rays' density (GlossySpecular.cosPower).
     */
    void weightedLobe(ShadeRec sr, Light light, double lightPdf, int lightSamples, MutableRgb fs) {
        double cosPower = lobe.cosPower(sr, sr.wo, sr.wi);
        fs.set(lobe.cs()).scale(lobe.scale() * cosPower);
        if (cosPower > 0) {
            double w = lightSampleWeight(sr, light, lightPdf, lightSamples, cosPower);
            if (w != 1) {
                fs.scale(w);
            }
        }
    }

    private double lightSampleWeight(ShadeRec sr, Light light, double lightPdf, int lightSamples, double cosPower) {
        if (!light.canBeHit() || sr.depth + 1 > sr.world.viewPlane().maxDepth()) {
            return 1;
        }
        RayTreePolicy policy = sr.scratch.policy;
        if (!policy.showsReflection(sr.depth)) {
            return 1;
        }
        MutableVec3 wi = sr.wi;
        int n = glossyRays(sr);
        // the glossy ray's weight f cos / pdf as GlossySpecular.sampleF gives it, over the rays:
        // the cutoff prunes the ray when that is below it (GlossyReflector)
        double k = lobe.scale() * 2 * Math.PI / (lobe.exp() + 1) * sr.normal.dot(wi);
        RGBColor cs = lobe.cs();
        if (!policy.wouldTrace(sr.depth, cs.r() * k / n, cs.g() * k / n, cs.b() * k / n)) {
            return 1;
        }
        double glossyPdf = (lobe.exp() + 1) / (2 * Math.PI) * cosPower;
        return powerHeuristic(lightSamples * lightPdf, n * glossyPdf);
    }

    /**
     * The weight of the radiance a glossy ray in direction {@code wi} found on the surface of a
     * light that this hit samples {@code lightSamples} times (0: not at all), whose sampling
     * would pick that direction with density {@code lightPdf}.
     */
    double glossyRayWeight(ShadeRec sr, MutableVec3 wi, int glossyRays, int lightSamples, double lightPdf) {
        if (lightSamples == 0) {
            return 1;
        }
        return powerHeuristic(glossyRays * lobe.pdf(sr, sr.wo, wi), lightSamples * lightPdf);
    }
}

package raytracer.core;

/**
 * Which parts of the ray tree a worker traces: the report's term passes ({@link ShadingPass}:
 * which terms the first hit shows) and the adaptive cutoff of Hall and Greenberg (1983): the path
 * weight of the ray at each depth, recorded as the materials branch, against the render's cutoff
 * ({@link RayTreeSettings}).
 * Materials ask it before they trace; no flag about either reaches the light loop. One per worker
 * ({@link WorkerScratch#policy}), since it records the weights as the recursion descends.
 */
public final class RayTreePolicy {
    /** The environment of the magenta-reflection pass (report figures 4c and 6c). */
    private static final Background MAGENTA = (ray, out) -> out.set(1, 0, 1);

    private final ShadingPass pass;
    private final double cutoff;
    /** The cutoff in radiance: a light sample is compared before the image's exposure scales it. */
    private final double radianceCutoff;
    /**
     * Path weight, per channel, of the ray traced at each depth: the product of the factors
     * (Fresnel fractions, mirror colours, Beer transmittances, glossy weights) that its radiance
     * will be multiplied by on its way back to the pixel. Depth 0 stays 1; materials set the deeper
     * slots through {@link #recordBranchWeight} just before they trace.
     */
    private final double[] weightR;
    private final double[] weightG;
    private final double[] weightB;

    /** For {@code levels} recursion depths, judging negligible light in the display units of {@code exposure}. */
    RayTreePolicy(RayTreeSettings settings, double exposure, int levels) {
        pass = settings.pass();
        cutoff = settings.cutoff();
        radianceCutoff = settings.cutoff() / exposure;
        weightR = new double[levels];
        weightG = new double[levels];
        weightB = new double[levels];
        weightR[0] = weightG[0] = weightB[0] = 1; // a camera ray carries all of its sample's weight
    }

    // ---- the report's term passes ----

    /** Whether a hit at {@code depth} shows its direct light (ambient and lights). */
    public boolean showsDirect(int depth) {
        return pass.direct(depth);
    }

    /** Whether a hit at {@code depth} traces its mirror or glossy reflection. */
    public boolean showsReflection(int depth) {
        return pass.reflection(depth);
    }

    /** Whether a hit at {@code depth} traces its refraction. */
    public boolean showsRefraction(int depth) {
        return pass.refraction(depth);
    }

    /** False in the ablation without Fresnel: reflected fractions do not vary with the angle. */
    public boolean angleDependent() {
        return pass.angleDependent();
    }

    /**
     * What the mirror rays of a hit at {@code depth} see when they escape: pure magenta for the
     * first hit of the magenta pass, otherwise the object's own reflection map ({@code own}, null
     * for the scene's background).
     */
    public Background reflectedEnvironment(int depth, Background own) {
        return pass.magentaReflection(depth) ? MAGENTA : own;
    }

    // ---- the adaptive ray-tree cutoff (Hall and Greenberg 1983) ----

    /**
     * Records the weight of the branch traced from {@code depth}, the parent's weight times the
     * factor (fr, fg, fb), and returns whether that branch is worth tracing: false when every
     * channel of its weight is below the cutoff, so whatever radiance L it would bring back
     * changes the pixel by less than cutoff * L.
     */
    public boolean recordBranchWeight(int depth, double fr, double fg, double fb) {
        double r = weightR[depth] * fr;
        double g = weightG[depth] * fg;
        double b = weightB[depth] * fb;
        weightR[depth + 1] = r;
        weightG[depth + 1] = g;
        weightB[depth + 1] = b;
        return Math.max(r, Math.max(g, b)) >= cutoff;
    }

    /**
     * Whether a branch of factor (fr, fg, fb) from {@code depth} would be traced
     * ({@link #recordBranchWeight}'s answer), without recording it.
     */
    public boolean wouldTrace(int depth, double fr, double fg, double fb) {
        return Math.max(weightR[depth] * fr, Math.max(weightG[depth] * fg, weightB[depth] * fb)) >= cutoff;
    }

    /**
     * How many of an area light's {@code samples} a hit at {@code depth} takes: all of them for
     * camera rays, and in proportion to the path weight (rounded down, at least one) below them
     * when the cutoff is on, since a hit weighing w adds w^2 of its estimate's variance to the
     * pixel. Each count gives an unbiased estimate; only the noise of faint, deep hits grows.
     */
    public int lightSamples(int depth, int samples) {
        if (cutoff == 0 || depth == 0) {
            return samples;
        }
        return Math.max(1, Math.min(samples, (int) (samples * weight(depth))));
    }

    /** The largest channel of the path weight of the ray traced at {@code depth}. */
    double weight(int depth) {
        return Math.max(weightR[depth], Math.max(weightG[depth], weightB[depth]));
    }

    /**
     * True when radiance {@code (r, g, b)} leaving a hit at {@code depth} would change the pixel by
     * less than the cutoff (in display units: 1 is white at the image's exposure); the shading
     * then need not trace the shadow ray that could only confirm it.
     */
    public boolean negligible(int depth, double r, double g, double b) {
        // max(r, g, b) < c, asked channel by channel: the same answer for every input (a NaN fails
        // both forms), without Math.max's NaN and -0.0 handling, a long blend sequence on the path
        // of every light sample; & rather than && keeps it free of branches
        double c = radianceCutoff;
        return r * weightR[depth] < c & g * weightG[depth] < c & b * weightB[depth] < c;
    }
}

package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.Rgb;
import raytracer.math.Rng;
import raytracer.math.ShearedRay;
import raytracer.math.Vec3;

/**
 * Everything one render worker overwrites while tracing: a ShadeRec, a ray and a colour per
 * recursion depth, a shadow ray, BVH traversal state, the random generator and the sample
 * buffers. Owned by one thread, so nothing on the per-ray path allocates or synchronises. Also
 * counts the rays it traced.
 */
public final class WorkerScratch {
    private final ShadeRec[] shadeRecs;
    private final Ray[] rays;
    private final Rgb[] colors;
    public final Ray shadowRay = new Ray();
    /** BVH traversal state: the subtrees still to visit and the slab-test constants of each traversal in progress. */
    public final TraversalStack traversals = new TraversalStack();
    /** The watertight triangle test's constants for the ray whose triangles are being tested. */
    public final ShearedRay shearedRay = new ShearedRay();
    /** Colour scratch for one light's incident radiance and the BRDF values that meet it. */
    public final Rgb lightScratch = new Rgb();
    public final Rgb brdfScratch = new Rgb();
    public final Rgb specularScratch = new Rgb();
    public final Rng rng = new Rng(0);
    public final Vec3 diskScratch = new Vec3();
    public final double[] sampleX;
    public final double[] sampleY;
    public final double[] lensX;
    public final double[] lensY;
    /** Sample pattern for the area light being shaded. */
    public final double[] lightX;
    public final double[] lightY;

    public long primaryRays;
    public long secondaryRays;
    public long shadowRays;
    /** Samples whose radiance came out NaN or infinite: dropped, counted, and expected to stay 0. */
    public long nonFiniteSamples;

    public WorkerScratch(World world) {
        int levels = world.viewPlane().maxDepth() + 2;
        shadeRecs = new ShadeRec[levels];
        rays = new Ray[levels];
        colors = new Rgb[levels];
        for (int i = 0; i < levels; i++) {
            shadeRecs[i] = new ShadeRec(world, this);
            rays[i] = new Ray();
            colors[i] = new Rgb();
        }
        int n = world.viewPlane().numSamples();
        sampleX = new double[n];
        sampleY = new double[n];
        lensX = new double[n];
        lensY = new double[n];
        int lightSamples = 1;
        for (Light light : world.lights()) {
            lightSamples = Math.max(lightSamples, world.viewPlane().sampler().supportedCount(light.sampleCount()));
        }
        lightX = new double[lightSamples];
        lightY = new double[lightSamples];
        environments = new Background[levels];
        patternX = new double[levels][];
        patternY = new double[levels][];
        weightR = new double[levels];
        weightG = new double[levels];
        weightB = new double[levels];
        weightR[0] = weightG[0] = weightB[0] = 1; // a camera ray carries all of its sample's weight
        cutoff = world.cutoff();
        radianceCutoff = world.cutoff() / world.viewPlane().exposure();
    }

    // ---- adaptive ray-tree depth (Hall and Greenberg 1983) ----
    /**
     * Path weight, per channel, of the ray traced at each depth: the product of the factors
     * (Fresnel fractions, mirror colours, Beer transmittances, glossy weights) that its radiance
     * will be multiplied by on its way back to the pixel. Depth 0 stays 1; materials set the deeper
     * slots through {@link #branch} just before they trace.
     */
    private final double[] weightR;
    private final double[] weightG;
    private final double[] weightB;
    private final double cutoff;
    private final double radianceCutoff;

    /**
     * Sets the weight of a branch traced from {@code depth} as the parent's weight times the
     * factor (fr, fg, fb) and says whether it is worth tracing: false when every channel of the
     * weight is below the world's cutoff, so whatever radiance L the branch would bring back
     * changes the pixel by less than cutoff * L.
     */
    public boolean branch(int depth, double fr, double fg, double fb) {
        double r = weightR[depth] * fr;
        double g = weightG[depth] * fg;
        double b = weightB[depth] * fb;
        weightR[depth + 1] = r;
        weightG[depth + 1] = g;
        weightB[depth + 1] = b;
        return Math.max(r, Math.max(g, b)) >= cutoff;
    }

    /**
     * How many of an area light's {@code samples} a hit at {@code depth} takes: all of them for
     * camera rays, and in proportion to the path weight below (rounded down, at least one) when the
     * cutoff is on,
     * since a hit weighing w adds w^2 of its estimate's variance to the pixel. Each count gives an
     * unbiased estimate; only the noise of faint, deep hits grows.
     */
    public int lightSamples(int depth, int samples) {
        if (cutoff == 0 || depth == 0) {
            return samples;
        }
        return Math.max(1, Math.min(samples, (int) (samples * weight(depth))));
    }

    /** The largest channel of the path weight of the ray traced at {@code depth}. */
    public double weight(int depth) {
        return Math.max(weightR[depth], Math.max(weightG[depth], weightB[depth]));
    }

    /**
     * True when radiance {@code (r, g, b)} leaving a hit at {@code depth} would change the pixel by
     * less than the cutoff (in display units: 1 is white at the image's exposure); the shading
     * then need not trace the shadow ray that could only confirm it.
     */
    public boolean negligible(int depth, double r, double g, double b) {
        return Math.max(r * weightR[depth], Math.max(g * weightG[depth], b * weightB[depth])) < radianceCutoff;
    }

    /** Bounding-volume tests made by all rays of this worker so far. */
    public long boxTests() {
        long sum = 0;
        for (ShadeRec sr : shadeRecs) {
            sum += sr.boxTests;
        }
        return sum;
    }

    private final Background[] environments;

    /**
     * Sets the environment that rays traced at {@code depth} see when they escape; null means the
     * scene's background. A material with its own reflection map sets it for the rays it spawns.
     */
    public void setEnvironment(int depth, Background environment) {
        environments[depth] = environment;
    }

    /** The environment for escaping rays at {@code depth}, or null for the scene's background. */
    public Background environment(int depth) {
        return environments[depth];
    }

    private final double[][] patternX;
    private final double[][] patternY;

    /**
     * Sample buffers for a material at {@code depth} (glossy rays), each one per depth so that the
     * recursion does not overwrite a pattern still in use; they grow once to the largest count.
     */
    public double[] patternX(int depth, int n) {
        if (patternX[depth] == null || patternX[depth].length < n) {
            patternX[depth] = new double[n];
            patternY[depth] = new double[n];
        }
        return patternX[depth];
    }

    /** The y buffer paired with {@link #patternX}; call that first. */
    public double[] patternY(int depth) {
        return patternY[depth];
    }

    /** The hit record for a ray traced at {@code depth}. */
    public ShadeRec shadeRec(int depth) {
        return shadeRecs[depth];
    }

    /** The ray slot for rays traced at {@code depth} (a material fills slot depth + 1). */
    public Ray ray(int depth) {
        return rays[depth];
    }

    /** The colour slot for radiance returned from {@code depth}. */
    public Rgb color(int depth) {
        return colors[depth];
    }
}

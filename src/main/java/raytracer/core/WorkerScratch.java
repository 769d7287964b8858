package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.Rng;
import raytracer.math.ShearedRay;
import raytracer.math.MutableVec3;

/**
 * Everything one render worker overwrites while tracing: a ShadeRec, a ray and a colour per
 * recursion depth, a shadow ray, BVH traversal state, the sample values and a random generator.
 * Owned by one thread, so nothing on the per-ray path allocates or synchronises. Also counts the
 * rays it traced, and holds the worker's {@link RayTreePolicy}.
 */
public final class WorkerScratch {
    private final World world;
    /** {@link ShadeRecSupply#FRESH}: a new hit record per ray (the allocation study), else the ones below. */
    private final boolean freshShadeRecs;
    private final ShadeRec[] shadeRecs;
    private final Ray[] rays;
    private final MutableRgb[] colors;
    private final MutableRgb[] weights;
    public final Ray shadowRay = new Ray();
    /** How many camera rays the renderer makes ahead of tracing them: a block of a pixel's samples. */
    public static final int CAMERA_RAYS = 16;
    private final Ray[] cameraRays = new Ray[CAMERA_RAYS];
    /** Where in its pixel each of those rays' samples lies, for a filter wider than the pixel. */
    public final double[] pixelU = new double[CAMERA_RAYS];
    public final double[] pixelV = new double[CAMERA_RAYS];
    /**
     * The objects that the camera rays of the tile being rendered can hit, in the order
     * {@link World#hit} searches them, or null for all: set by the renderer per tile when the
     * world {@linkplain World#searchesByTile searches by tile}.
     */
    public GeometricObject[] cameraRayObjects;
    /** BVH traversal state: the subtrees still to visit and the slab-test constants of each traversal in progress. */
    public final TraversalStack traversals = new TraversalStack();
    /** The watertight triangle test's constants for the ray whose triangles are being tested. */
    public final ShearedRay shearedRay = new ShearedRay();
    /** Colour scratch for one light's incident radiance and the BRDF values that meet it. */
    public final MutableRgb lightScratch = new MutableRgb();
    public final MutableRgb brdfScratch = new MutableRgb();
    public final MutableRgb specularScratch = new MutableRgb();
    /**
     * Free random numbers for code outside the sampled dimensions, reseeded by the renderer for
     * each pixel sample; the renderer's own values come from {@link #samples}.
     */
    public final Rng rng = new Rng(0);
    public final MutableVec3 diskScratch = new MutableVec3();
    /** The values of every sampled dimension: pixel position, lens, lights, glossy rays. */
    public final PixelSamples samples;
    /** The passes and the adaptive cutoff, with this worker's path weights. */
    public final RayTreePolicy policy;

    public long primaryRays;
    public long secondaryRays;
    public long shadowRays;
    /** Samples whose radiance came out NaN or infinite: dropped, counted, and expected to stay 0. */
    public long nonFiniteSamples;
    /** Work the scene analysis left out, counted where it would have been done: one count per {@link Skipped} kind. */
    public final long[] skipped = new long[Skipped.KINDS];

    /** Starts pixel sample {@code j}: its sample values, the free generator reseeded from them, and its camera ray counted. */
    public void startSample(int j) {
        samples.startSample(j);
        rng.reseed(samples.sampleKey(j));
        primaryRays++;
    }

    /**
     * {@code L}, or black when it came out NaN or infinite: such a sample is counted and reported
     * (a defect to fix, never a pixel to show) and weighs as a black one.
     */
    public MutableRgb finite(MutableRgb L) {
        if (!(Double.isFinite(L.r) && Double.isFinite(L.g) && Double.isFinite(L.b))) {
            nonFiniteSamples++;
            L.setBlack();
        }
        return L;
    }

    /** Scratch for a render of {@code world} that traces every term of the whole tree. */
    public WorkerScratch(World world) {
        this(world, RayTreeSettings.FULL_TREE);
    }

    /** Scratch for a render of {@code world} that traces as much of the ray tree as {@code settings} ask. */
    public WorkerScratch(World world, RayTreeSettings settings) {
        this(world, settings, ShadeRecSupply.REUSE);
    }

    /** As {@link #WorkerScratch(World, RayTreeSettings)}, with hit records from {@code supply}. */
    public WorkerScratch(World world, RayTreeSettings settings, ShadeRecSupply supply) {
        this.world = world;
        this.freshShadeRecs = supply == ShadeRecSupply.FRESH;
        int levels = world.viewPlane().maxDepth() + 2;
        shadeRecs = new ShadeRec[levels];
        rays = new Ray[levels];
        colors = new MutableRgb[levels];
        weights = new MutableRgb[levels];
        for (int i = 0; i < levels; i++) {
            shadeRecs[i] = new ShadeRec(world, this);
            rays[i] = new Ray();
            colors[i] = new MutableRgb();
            weights[i] = new MutableRgb();
        }
        for (int i = 0; i < CAMERA_RAYS; i++) {
            cameraRays[i] = new Ray();
        }
        samples = new PixelSamples(levels);
        // a scratch used without a renderer (a test tracing one ray) draws pixel (0, 0), sample 0, seed 0
        samples.startPixel(new SampleTables(world.viewPlane().sampler(), world.viewPlane().numSamples(), 0), 0, 0);
        samples.startSample(0);
        environments = new Background[levels];
        emitters = new Light[levels];
        emitterPdfs = new double[levels];
        policy = new RayTreePolicy(settings, world.viewPlane().exposure(), levels);
    }

    /**
     * Bounding-volume tests made by all rays of this worker so far (with {@link ShadeRecSupply#FRESH},
     * the fresh records' tests are not counted).
     */
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

    /** Per depth: the light whose emitting surface the ray traced there hit, and that light's density for the ray's direction. */
    private final Light[] emitters;
    private final double[] emitterPdfs;

    /**
     * Notes that the ray traced at {@code depth} hit the visible surface of {@code light}, whose
     * own sampling would pick that direction with solid-angle density {@code pdf}: a material that
     * also samples the light weighs what the ray brought back against it (multiple importance
     * sampling). Cleared by {@link #clearEmitter} before the ray is traced.
     */
    public void recordEmitter(int depth, Light light, double pdf) {
        emitters[depth] = light;
        emitterPdfs[depth] = pdf;
    }

    public void clearEmitter(int depth) {
        emitters[depth] = null;
    }

    /** The light whose surface the ray traced at {@code depth} hit, or null. */
    public Light emitter(int depth) {
        return emitters[depth];
    }

    /** That light's solid-angle density for the ray's direction ({@link #recordEmitter}). */
    public double emitterPdf(int depth) {
        return emitterPdfs[depth];
    }

    /** The environment for escaping rays at {@code depth}, or null for the scene's background. */
    public Background environment(int depth) {
        return environments[depth];
    }

    /**
     * The hit record for a ray traced at {@code depth}: this worker's own for that depth, or a new
     * one for each call when the supply is {@link ShadeRecSupply#FRESH}. The test of a final field
     * always goes the same way, so the reusing path pays a predicted branch and no more.
     */
    public ShadeRec shadeRec(int depth) {
        if (freshShadeRecs) {
            return new ShadeRec(world, this);
        }
        return shadeRecs[depth];
    }

    /** Camera ray slot {@code k}, 0 &lt;= k &lt; {@link #CAMERA_RAYS}, for rays made ahead of tracing. */
    public Ray cameraRay(int k) {
        return cameraRays[k];
    }

    /** The ray slot for rays traced at {@code depth} (a material fills slot depth + 1). */
    public Ray ray(int depth) {
        return rays[depth];
    }

    /** The colour slot for radiance returned from {@code depth}. */
    public MutableRgb color(int depth) {
        return colors[depth];
    }

    /**
     * The colour slot for the weight of a direction sampled by a material at {@code depth} (a
     * BRDF's or BTDF's sampleF): one per depth, as it is still needed when the traced ray returns.
     */
    public MutableRgb weight(int depth) {
        return weights[depth];
    }
}

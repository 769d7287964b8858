package raytracer.core;

/**
 * What the scene analysis leaves out of a render, one kind of work each: {@link Skip} names the
 * kind a decision saves, and each worker counts in {@link WorkerScratch#skipped} the work of that
 * kind it did not do, where it would have done it, so that --stats can give the saving as counts.
 */
public final class Skipped {
    /** Shadow rays not traced, for lights that nothing can hide from a visible point. */
    public static final int SHADOW_RAYS = 0;
    /** Secondary rays of zero weight not traced. */
    public static final int SECONDARY_RAYS = 1;
    /** Ambient terms not evaluated (ka = 0, or no ambient light). */
    public static final int AMBIENT_TERMS = 2;
    /** Diffuse BRDF evaluations left out (kd = 0). */
    public static final int DIFFUSE_TERMS = 3;
    /** Specular lobe evaluations left out (ks = 0). */
    public static final int SPECULAR_LOBES = 4;
    /** Light samples not evaluated on surfaces that reflect no direct light (every term zero). */
    public static final int LIGHT_SAMPLES = 5;
    /** Hits whose u, v were not computed (a sphere's or cylinder's inverse trigonometry), as no texture reads them. */
    public static final int TEXTURE_COORDINATES = 6;
    /** Camera rays' tests of objects that their tile's view volume excludes, not made. */
    public static final int OBJECT_TESTS = 7;
    /** How many kinds there are. */
    public static final int KINDS = 8;
    /** A decision whose saving is not counted while rendering (memory, a build, a lookup). */
    public static final int UNCOUNTED = -1;

    private static final String[] NAMES = {"shadow rays", "secondary rays", "ambient terms", "diffuse terms",
        "specular lobes", "light samples", "texture coordinates", "object tests"};

    private Skipped() {
    }

    /** What a count of {@code kind} counts ("shadow rays"), for --stats. */
    public static String name(int kind) {
        return NAMES[kind];
    }
}

package raytracer.core;

import raytracer.math.Hashes;

/**
 * The sample values of one worker: each 2D value is a pure function of (seed, pixel, sample index,
 * dimension), as pbrt-v4's samplers make them, so no sample's draws (or a branch the cutoff prunes)
 * shift another's, and tiles may be rendered by any thread in any order.
 *
 * <p>A dimension is named by where it is used and what for: the path of branches from the camera
 * ray down to the hit ({@link #branch}: which mirror, refracted or glossy ray) and the purpose
 * (pixel position, lens, light l, glossy direction). It is never named by a count of values drawn
 * before, as a plain generator's would be.
 *
 * <p>Stratified across the pixel: in each dimension the pixel's {@code spp} samples share one
 * pattern of spp * B points, where B is how many values one sample takes there (a light's samples
 * per hit, times the glossy rays of the hits above it). Sample i takes B of them, so a 16-spp pixel
 * with one light sample per hit puts its 16 light samples on one stratified 16-point pattern over
 * the light. Patterns of different dimensions are shuffled independently (Suffern's shuffled
 * indices, section 5.3; "padding", Kollig and Keller 2002), so no dimension's strata line up with
 * another's. For a pointwise sampler (Sobol') sample i takes the aligned block p(i) B .. p(i) B +
 * B - 1 of the sequence, p a hashed permutation of the samples (Kensler 2013): each such block of
 * a (0,2)-sequence is itself stratified, so the B light samples of one hit are too. Where spp * B
 * would exceed {@link #maxPoints}, each of the B values gets a dimension of its own, stratified
 * across the pixel's samples only.
 */
public final class PixelSamples {
    /** Purposes of a dimension. */
    public static final int PIXEL = 1;
    public static final int LENS = 2;
    public static final int GLOSSY = 3;
    /** Light l of the world's list samples dimension LIGHT + l. */
    public static final int LIGHT = 16;

    /** Branch slots: which of a hit's rays a path continues along. */
    public static final int REFLECTED = 1;
    public static final int REFRACTED = 2;
    public static final int GLOSSY_RAY = 3;
    private static final int INHERITED = 4;
    private static final long BRANCH = 0x5bd1e995L << 32;

    /** Largest pattern drawn whole for a book sampler; pointwise samplers go further at no cost. */
    static final int MAX_SET_POINTS = 1 << 12;
    static final int MAX_SEQUENCE_POINTS = 1 << 24;

    private final Sampler sampler;
    private final boolean pointwise;
    private final int spp;
    private final int maxPoints;
    private final SampleSets sets;

    private long pixelKey;
    private int sample;
    /** Per depth: the path's key, the offset of this ray among the B of its sample, and B. */
    private final long[] pathKey;
    private final int[] pathOffset;
    private final int[] pathBlock;

    /** The last value drawn by {@link #get2D}, each in [0, 1). */
    public double u;
    public double v;

    /** For renders of {@code spp} samples per pixel from {@code sampler}, with rays down to {@code levels - 1}. */
    public PixelSamples(Sampler sampler, int spp, int levels) {
        this.sampler = sampler;
        this.pointwise = sampler.pointwise();
        this.spp = spp;
        this.maxPoints = pointwise ? MAX_SEQUENCE_POINTS : MAX_SET_POINTS;
        this.sets = pointwise ? null : new SampleSets(sampler);
        pathKey = new long[levels];
        pathOffset = new int[levels];
        pathBlock = new int[levels];
    }

    /** Starts pixel (x, y) of a render seeded {@code seed}. */
    public void startPixel(long seed, int x, int y) {
        pixelKey = Hashes.mix(seed, (long) y << 32 | (x & 0xffffffffL));
        if (sets != null) {
            sets.clear();
        }
    }

    /** Starts sample {@code i} of the pixel (0 &lt;= i &lt; spp): its camera ray is the root of the path. */
    public void startSample(int i) {
        sample = i;
        pathKey[0] = 0;
        pathOffset[0] = 0;
        pathBlock[0] = 1;
    }

    /** A key for sample {@code i} of the current pixel, for generators that need one. */
    public long sampleKey(int i) {
        return Hashes.mix(pixelKey, i);
    }

    /**
     * Names the path of the ray that a hit at {@code depth} is about to trace: its ray {@code j}
     * of {@code k} (0 of 1 for a mirror or refracted ray) in {@code slot}.
     */
    public void branch(int depth, int slot, int j, int k) {
        long key = Hashes.mix(pathKey[depth], BRANCH + slot);
        long block = (long) pathBlock[depth] * k;
        long offset = (long) pathOffset[depth] * k + j;
        if (block * spp > maxPoints) {
            key = Hashes.mix(key, offset);
            block = 1;
            offset = 0;
        }
        pathKey[depth + 1] = key;
        pathBlock[depth + 1] = (int) block;
        pathOffset[depth + 1] = (int) offset;
    }

    /**
     * Gives the rays that a hit at {@code depth} traces a path of their own until its material
     * names them by {@link #branch}, so a material that does not still draws pure values.
     */
    public void inherit(int depth) {
        pathKey[depth + 1] = Hashes.mix(pathKey[depth], BRANCH + INHERITED);
        pathBlock[depth + 1] = pathBlock[depth];
        pathOffset[depth + 1] = pathOffset[depth];
    }

    /**
     * Draws into ({@link #u}, {@link #v}) value {@code s} of the {@code m} that a hit at
     * {@code depth} takes for {@code purpose} (m is the most it ever takes there: a hit that takes
     * fewer uses the first ones).
     */
    public void get2D(int depth, int purpose, int s, int m) {
        long key = Hashes.mix(pathKey[depth], purpose);
        long block = (long) pathBlock[depth] * m;
        long offset = (long) pathOffset[depth] * m + s;
        if (block * spp > maxPoints) {
            key = Hashes.mix(key, offset);
            block = 1;
            offset = 0;
        }
        long dimension = Hashes.mix(pixelKey, key);
        if (pointwise) {
            int index = Hashes.permute(sample, spp, (int) dimension) * (int) block + (int) offset;
            long bits = sampler.point(index, Hashes.mix(dimension));
            u = (bits >>> 32) * 0x1.0p-32;
            v = (bits & 0xffffffffL) * 0x1.0p-32;
        } else {
            int set = sets.find(dimension, spp * (int) block);
            int at = (sample * (int) block + (int) offset) % sets.size(set);
            u = sets.x(set)[at];
            v = sets.y(set)[at];
        }
    }
}

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
 * per hit, times the glossy rays of the hits above it). Sample i takes the block p(i) B .. p(i) B +
 * B - 1 of it, p a permutation of the samples. So a 16-spp pixel with one light sample per hit puts
 * its 16 light samples on one stratified 16-point pattern over the light. Pattern and permutation
 * are picked from the render's {@link SampleTables} by a hash of (pixel, dimension): different
 * dimensions are shuffled independently (Suffern's shuffled indices, section 5.3; "padding",
 * Kollig and Keller 2002), so no dimension's strata line up with another's. Where spp * B would
 * exceed {@link #MAX_POINTS}, each of the B values gets a dimension of its own, stratified across
 * the pixel's samples only.
 */
public final class PixelSamples {
    /** Purposes of a dimension. */
    public static final int PIXEL = 1;
    public static final int LENS = 2;
    public static final int GLOSSY = 3;
    /** Light number l ({@link Light#number}) samples dimension LIGHT + l. */
    public static final int LIGHT = 16;

    /** Branch slots: which of a hit's rays a path continues along. */
    public static final int REFLECTED = 1;
    public static final int REFRACTED = 2;
    public static final int GLOSSY_RAY = 3;
    private static final int INHERITED = 4;
    private static final long BRANCH = 0x5bd1e995L << 32;
    private static final long PURPOSE = 0xC2B2AE3D27D4EB4FL;

    /** Largest pattern a dimension's samples share. */
    static final int MAX_POINTS = 1 << 12;

    private SampleTables tables;
    private int spp;
    private long pixelKey;
    private int sample;
    /** Per depth: the path's key, the offset of this ray among the B of its sample, and B. */
    private final long[] pathKey;
    private final int[] pathOffset;
    private final int[] pathBlock;
    /** The last patterns used, by size: most renders use one or two sizes. */
    private SampleTables.Patterns recent;
    private SampleTables.Patterns other;

    /** The last value drawn by {@link #get2D}, each in [0, 1). */
    public double u;
    public double v;

    /** For rays traced down to depth {@code levels - 1}. */
    public PixelSamples(int levels) {
        pathKey = new long[levels];
        pathOffset = new int[levels];
        pathBlock = new int[levels];
    }

    /** Starts pixel (x, y) of the render whose sets are {@code tables}. */
    public void startPixel(SampleTables tables, int x, int y) {
        if (tables != this.tables) {
            this.tables = tables;
            spp = tables.spp();
            recent = null;
            other = null;
        }
        pixelKey = Hashes.mix(tables.seed(), (long) y << 32 | (x & 0xffffffffL));
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
        if (block * spp > MAX_POINTS && block > 1) {
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
        long key = pathKey[depth] ^ purpose * PURPOSE;
        int block = pathBlock[depth] * m;
        int offset = pathOffset[depth] * m + s;
        if ((long) block * spp > MAX_POINTS && block > 1) {
            key = Hashes.mix(key, offset);
            block = 1;
            offset = 0;
        }
        long dimension = Hashes.mix(pixelKey ^ key);
        SampleTables.Patterns p = patterns(spp * block);
        int at = ((int) dimension & p.mask()) * p.size() + tables.permuted((int) (dimension >>> 32), sample) * block + offset;
        u = p.xs()[at];
        v = p.ys()[at];
    }

    private SampleTables.Patterns patterns(int size) {
        SampleTables.Patterns p = recent;
        if (p != null && p.size() == size) {
            return p;
        }
        p = other;
        if (p == null || p.size() != size) {
            p = tables.patterns(size);
        }
        other = recent;
        recent = p;
        return p;
    }
}

package raytracer.accel;

import raytracer.core.ShadeRec;
import raytracer.math.Ray;

/**
 * A BVH flattened into arrays for traversal. Each interior node is one record of 16 ints (64
 * bytes, a cache line), records in depth-first order of the interior nodes: both children's boxes
 * as floats rounded outward, so a box never shrinks ({@link #LEFT_BOX}, {@link #RIGHT_BOX}, six
 * each: x0, y0, z0, x1, y1, z1), then each child's link ({@link #LINK}) and primitive count
 * ({@link #COUNT}). A leaf child has a count above 0 and links to its first entry in
 * {@link #order} (its primitives are order[link .. link + count)); an interior child has count 0
 * and links to its record. Testing both children from their parent's record reads one line per
 * visited node (see README, "BVH layout"). The root's own box, link and count are kept apart.
 */
public final class FlatBVH {
    /** Deepest tree the builders produce; traversal stacks are this big. */
    public static final int MAX_DEPTH = 64;
    static final int RECORD = 16;
    static final int LEFT_BOX = 0;
    static final int RIGHT_BOX = 6;
    static final int LINK = 12;
    static final int COUNT = 14;

    final int[] records;
    final int[] order;
    private final int nodeCount;
    /** The root's box as float bits (rounded outward), its link and count, as a record's child entries. */
    final int[] rootBox;
    final int rootLink;
    final int rootCount;

    FlatBVH(int[] records, int[] order, int[] rootBox, int rootLink, int rootCount, int nodeCount) {
        this.records = records;
        this.order = order;
        this.rootBox = rootBox;
        this.rootLink = rootLink;
        this.rootCount = rootCount;
        this.nodeCount = nodeCount;
    }

    /**
     * Packs a tree given node by node in depth-first order, as the SAH builder makes it: node i's
     * left child is i + 1; {@code meta[2i]} is the right child (interior) or the first entry in
     * {@code order} (leaf), {@code meta[2i + 1]} is negative for an interior node or the primitive
     * count of a leaf; {@code bounds[6i .. 6i + 6)} is node i's box.
     */
    static FlatBVH fromNodes(double[] bounds, int[] meta, int[] order, int nodeCount) {
        int[] record = new int[nodeCount];
        int interior = 0;
        for (int node = 0; node < nodeCount; node++) {
            record[node] = meta[2 * node + 1] > 0 ? -1 : interior++;
        }
        int[] records = new int[RECORD * interior];
        for (int node = 0; node < nodeCount; node++) {
            if (record[node] < 0) {
                continue;
            }
            int r = RECORD * record[node];
            int[] children = {node + 1, meta[2 * node]};
            for (int side = 0; side < 2; side++) {
                int child = children[side];
                packBox(bounds, child, records, r + (side == 0 ? LEFT_BOX : RIGHT_BOX));
                boolean leaf = record[child] < 0;
                records[r + LINK + side] = leaf ? meta[2 * child] : record[child];
                records[r + COUNT + side] = leaf ? meta[2 * child + 1] : 0;
            }
        }
        int[] rootBox = new int[6];
        packBox(bounds, 0, rootBox, 0);
        boolean rootIsLeaf = record[0] < 0;
        return new FlatBVH(records, order, rootBox, rootIsLeaf ? meta[0] : 0, rootIsLeaf ? meta[1] : 0, nodeCount);
    }

    private static void packBox(double[] bounds, int node, int[] out, int at) {
        for (int k = 0; k < 3; k++) {
            out[at + k] = Float.floatToRawIntBits(roundDown(bounds[6 * node + k]));
            out[at + 3 + k] = Float.floatToRawIntBits(roundUp(bounds[6 * node + 3 + k]));
        }
    }

    /** The largest float not above d (infinite beyond the float range). */
    static float roundDown(double d) {
        float f = (float) d;
        return f > d ? Math.nextDown(f) : f;
    }

    /** The smallest float not below d. */
    static float roundUp(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }

    public int nodeCount() {
        return nodeCount;
    }

    public int primitiveCount() {
        return order.length;
    }

    /** Coordinate k (x0, y0, z0, x1, y1, z1) of the root's box. */
    double rootBound(int k) {
        return Float.intBitsToFloat(rootBox[k]);
    }

    /** Depth of the deepest leaf, for statistics. */
    public int depth() {
        return rootCount > 0 ? 1 : 1 + recordDepth(rootLink);
    }

    private int recordDepth(int record) {
        int deepest = 0;
        for (int side = 0; side < 2; side++) {
            int r = RECORD * record;
            deepest = Math.max(deepest, records[r + COUNT + side] > 0 ? 1 : 1 + recordDepth(records[r + LINK + side]));
        }
        return deepest;
    }

    /** Far slab distances are widened by this factor so rounding never culls a box the ray touches. */
    private static final double WIDEN = 1 + 2 * raytracer.math.Rounding.gamma(3);

    /**
     * The distance at which the ray enters the box stored as six float bit patterns
     * (x0, y0, z0, x1, y1, z1) at {@code b[i..i+6)}, clamped to 0 when it starts inside, or
     * +infinity when it misses the box on (0, tMax). The ray comes as primitives, loaded once per
     * traversal: origin, 1/d, 1/d widened for the far planes (pbrt-v3, section 3.9.2) and the
     * offset (0 or 3) of each axis's near plane.
     *
     * <p>With finite inverses no slab distance is NaN, and Math.max/min combine them without a
     * branch (the ordered comparisons compile to branches that the CPU mispredicts: 10-20% slower
     * in a same-JVM test of the traversal alone). A ray parallel to an axis has an infinite 1/d, and
     * an origin on a slab plane of that axis gives 0 * infinity = NaN; for such rays
     * ({@code parallel}) the comparisons are ordered so that a NaN imposes no constraint.
     */
    static double entry(int[] b, int i, double ox, double oy, double oz, double ix, double iy, double iz,
                        double fx, double fy, double fz, int nx, int ny, int nz, double tMax, boolean parallel) {
        if (parallel) {
            return entryParallel(b, i, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tMax);
        }
        double tx0 = (Float.intBitsToFloat(b[i + nx]) - ox) * ix;
        double tx1 = (Float.intBitsToFloat(b[i + 3 - nx]) - ox) * fx;
        double ty0 = (Float.intBitsToFloat(b[i + 1 + ny]) - oy) * iy;
        double ty1 = (Float.intBitsToFloat(b[i + 4 - ny]) - oy) * fy;
        double tz0 = (Float.intBitsToFloat(b[i + 2 + nz]) - oz) * iz;
        double tz1 = (Float.intBitsToFloat(b[i + 5 - nz]) - oz) * fz;
        double t0 = Math.max(Math.max(tx0, ty0), Math.max(tz0, 0));
        double t1 = Math.min(Math.min(tx1, ty1), Math.min(tz1, tMax));
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    /**
     * {@link #entry} for rays parallel to an axis, in a method of its own: most renders never call
     * it, so the JIT leaves it out of the compiled traversal, which then compiles faster.
     */
    private static double entryParallel(int[] b, int i, double ox, double oy, double oz, double ix, double iy,
                                        double iz, double fx, double fy, double fz, int nx, int ny, int nz,
                                        double tMax) {
        double tx0 = (Float.intBitsToFloat(b[i + nx]) - ox) * ix;
        double tx1 = (Float.intBitsToFloat(b[i + 3 - nx]) - ox) * fx;
        double ty0 = (Float.intBitsToFloat(b[i + 1 + ny]) - oy) * iy;
        double ty1 = (Float.intBitsToFloat(b[i + 4 - ny]) - oy) * fy;
        double tz0 = (Float.intBitsToFloat(b[i + 2 + nz]) - oz) * iz;
        double tz1 = (Float.intBitsToFloat(b[i + 5 - nz]) - oz) * fz;
        double t0 = tx0 > 0 ? tx0 : 0;
        double t1 = tx1 < tMax ? tx1 : tMax;
        t0 = ty0 > t0 ? ty0 : t0;
        t1 = ty1 < t1 ? ty1 : t1;
        t0 = tz0 > t0 ? tz0 : t0;
        t1 = tz1 < t1 ? tz1 : t1;
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    /** True when a widened inverse direction is infinite (or NaN): the ray needs the NaN-safe slab test. */
    private static boolean parallel(double fx, double fy, double fz) {
        return !(Math.abs(fx) <= Double.MAX_VALUE && Math.abs(fy) <= Double.MAX_VALUE && Math.abs(fz) <= Double.MAX_VALUE);
    }

    /**
     * Closest-hit traversal. Both children are tested from their parent's record; the ray descends
     * into the one it enters first and stacks the other with its entry distance, which is skipped
     * when popped if a hit closer than that has been found meanwhile. The stack holds (link, count)
     * pairs.
     */
    boolean closestHit(Ray ray, ShadeRec sr, Leaves leaves) {
        double ox = ray.ox;
        double oy = ray.oy;
        double oz = ray.oz;
        double ix = ray.invDx;
        double iy = ray.invDy;
        double iz = ray.invDz;
        double fx = ix * WIDEN;
        double fy = iy * WIDEN;
        double fz = iz * WIDEN;
        int nx = ray.nearX;
        int ny = ray.nearY;
        int nz = ray.nearZ;
        boolean parallel = parallel(fx, fy, fz);
        double tHit = sr.t;
        sr.boxTests++;
        if (!(entry(rootBox, 0, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tHit, parallel) < tHit)) {
            return false;
        }
        int[] nodes = records;
        long tests = 0;
        int[] stack = sr.traversalStack;
        double[] stackT = sr.traversalEntry;
        int base = sr.stackBase;
        int sp = base;
        sr.stackBase = base + MAX_DEPTH;
        boolean hit = false;
        int link = rootLink;
        int count = rootCount;
        while (true) {
            if (count > 0) {
                if (leaves.hit(link, count, ray, sr)) {
                    hit = true;
                    tHit = sr.t;
                }
            } else {
                int r = RECORD * link;
                tests += 2;
                double tLeft = entry(nodes, r + LEFT_BOX, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tHit, parallel);
                double tRight = entry(nodes, r + RIGHT_BOX, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tHit, parallel);
                if (tLeft < Double.POSITIVE_INFINITY) {
                    if (tRight < Double.POSITIVE_INFINITY) {
                        int far = tLeft <= tRight ? 1 : 0;
                        stack[2 * sp] = nodes[r + LINK + far];
                        stack[2 * sp + 1] = nodes[r + COUNT + far];
                        stackT[sp++] = far == 1 ? tRight : tLeft;
                        link = nodes[r + LINK + 1 - far];
                        count = nodes[r + COUNT + 1 - far];
                    } else {
                        link = nodes[r + LINK];
                        count = nodes[r + COUNT];
                    }
                    continue;
                }
                if (tRight < Double.POSITIVE_INFINITY) {
                    link = nodes[r + LINK + 1];
                    count = nodes[r + COUNT + 1];
                    continue;
                }
            }
            // pop the next subtree that may still hold a closer hit
            do {
                if (sp == base) {
                    sr.stackBase = base;
                    sr.boxTests += tests;
                    return hit;
                }
                sp--;
                link = stack[2 * sp];
                count = stack[2 * sp + 1];
            } while (stackT[sp] >= tHit);
        }
    }

    /** Any-hit traversal for shadow rays: no ordering, stops at the first blocker. */
    boolean anyHit(Ray ray, double tMax, ShadeRec sr, Leaves leaves) {
        double ox = ray.ox;
        double oy = ray.oy;
        double oz = ray.oz;
        double ix = ray.invDx;
        double iy = ray.invDy;
        double iz = ray.invDz;
        double fx = ix * WIDEN;
        double fy = iy * WIDEN;
        double fz = iz * WIDEN;
        int nx = ray.nearX;
        int ny = ray.nearY;
        int nz = ray.nearZ;
        boolean parallel = parallel(fx, fy, fz);
        sr.boxTests++;
        if (!(entry(rootBox, 0, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tMax, parallel) < tMax)) {
            return false;
        }
        int[] nodes = records;
        long tests = 0;
        int[] stack = sr.traversalStack;
        int base = sr.stackBase;
        int sp = base;
        sr.stackBase = base + MAX_DEPTH;
        boolean blocked = false;
        int link = rootLink;
        int count = rootCount;
        while (!blocked) {
            if (count > 0) {
                blocked = leaves.shadowHit(link, count, ray, tMax, sr);
            } else {
                int r = RECORD * link;
                tests += 2;
                boolean hitLeft = entry(nodes, r + LEFT_BOX, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tMax, parallel)
                                  < Double.POSITIVE_INFINITY;
                boolean hitRight = entry(nodes, r + RIGHT_BOX, ox, oy, oz, ix, iy, iz, fx, fy, fz, nx, ny, nz, tMax, parallel)
                                   < Double.POSITIVE_INFINITY;
                if (hitLeft) {
                    if (hitRight) {
                        stack[2 * sp] = nodes[r + LINK + 1];
                        stack[2 * sp + 1] = nodes[r + COUNT + 1];
                        sp++;
                    }
                    link = nodes[r + LINK];
                    count = nodes[r + COUNT];
                    continue;
                }
                if (hitRight) {
                    link = nodes[r + LINK + 1];
                    count = nodes[r + COUNT + 1];
                    continue;
                }
            }
            if (sp == base) {
                break;
            }
            sp--;
            link = stack[2 * sp];
            count = stack[2 * sp + 1];
        }
        sr.stackBase = base;
        sr.boxTests += tests;
        return blocked;
    }
}

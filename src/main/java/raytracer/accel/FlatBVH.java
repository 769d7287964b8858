package raytracer.accel;

import java.util.List;
import raytracer.core.ShadeRec;
import raytracer.core.TraversalStack;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Ray;
import raytracer.math.SlabRay;

/**
 * A BVH flattened into arrays, and its traversal (report section 6): the interior nodes, four
 * children wide ({@link WideNodes}, collapsed from a builder's binary tree by {@link WideCollapse}),
 * the root apart (its box, and its link and count as a node stores a child's), and the leaf
 * order, which lists the primitives so that every leaf's are one run of it. What a leaf holds and
 * how it is tested is the business of {@link Leaves}. A tree over primitives already renumbered in
 * its leaf order (a mesh's triangles, {@link #inLeafOrder}) keeps no order: it would be 0, 1, 2,
 * ..., four bytes a triangle for nothing.
 */
public final class FlatBVH {
    /** The deepest binary tree the builders may produce (a wide tree is no deeper), which the traversal stacks have room for. */
    public static final int MAX_DEPTH = TraversalStack.MAX_DEPTH;

    /** The node test, a constant the JIT inlines. */
    private static final NodeTest TEST = NodeTest.CHOSEN;

    final WideNodes nodes;
    /**
     * Primitive ids in leaf order: a leaf (link, count) holds order[link .. link + count - 1]; null
     * when the primitives are numbered in leaf order, so that the leaf holds link .. link + count - 1.
     */
    final int[] order;
    private final int primitives;
    final float[] rootBox;
    final int rootLink;
    final int rootCount;
    /** The whole tree, where every search starts unless told otherwise. */
    final Start root;

    /**
     * Where a search starts: a subtree, given by its link and count as a node stores a child, and
     * its box, the floats {@code box[at .. at + 6)}.
     */
    record Start(float[] box, int at, int link, int count) {
    }

    /** A tree whose primitives are numbered in its leaf order when {@code order} is null. */
    FlatBVH(WideNodes nodes, int[] order, int primitives, float[] rootBox, int rootLink, int rootCount) {
        if (order != null && order.length != primitives) {
            throw new IllegalArgumentException("the leaf order lists " + order.length + " of " + primitives + " primitives");
        }
        this.nodes = nodes;
        this.order = order;
        this.primitives = primitives;
        this.rootBox = rootBox;
        this.rootLink = rootLink;
        this.rootCount = rootCount;
        this.root = new Start(rootBox, 0, rootLink, rootCount);
    }

    /**
     * The subtree where the search of a ray that stays in {@code volume} may start, or null when
     * no such ray can reach a leaf: from the root down, as long as the volume wholly excludes all
     * but one child's box ({@link HalfSpace#excludes}, a margin far above the slab test's
     * rounding). Such a ray misses the excluded boxes, so from the root it would have tested every
     * box of every node above the subtree, stacked nothing, and gone on into the subtree: starting
     * there, it tests the subtree's box, as it did from its parent, and then visits the same nodes
     * in the same order, with the same hits. (Reshetov, Soupikov and Hurley's entry points for the
     * rays of a frustum, "Multi-level ray tracing algorithm", SIGGRAPH 2005, made exact.)
     */
    Start startFor(List<HalfSpace> volume) {
        if (excluded(rootBox, 0, volume)) {
            return null;
        }
        Start start = root;
        while (start.count() == 0) {
            int node = start.link();
            int seen = -1;
            int lanes = 0;
            for (int lane = 0; lane < WideNodes.WIDTH; lane++) {
                if (nodes.primitiveCount(node, lane) != WideNodes.EMPTY && !excluded(nodes.box(node, lane), 0, volume)) {
                    seen = lane;
                    lanes++;
                }
            }
            if (lanes != 1) {
                return lanes > 1 ? start : null;
            }
            start = new Start(nodes.box(node, seen), 0, nodes.link(node, seen), nodes.primitiveCount(node, seen));
        }
        return start;
    }

    private static boolean excluded(float[] box, int at, List<HalfSpace> volume) {
        BBox b = new BBox(box[at], box[at + 1], box[at + 2], box[at + 3], box[at + 4], box[at + 5]);
        for (HalfSpace face : volume) {
            if (face.excludes(b)) {
                return true;
            }
        }
        return false;
    }

    /** All nodes, leaves included. */
    public int nodeCount() {
        if (rootCount > 0) {
            return 1;
        }
        int leaves = 0;
        for (int node = 0; node < nodes.count(); node++) {
            for (int lane = 0; lane < WideNodes.WIDTH; lane++) {
                leaves += nodes.primitiveCount(node, lane) > 0 ? 1 : 0;
            }
        }
        return nodes.count() + leaves;
    }

    public int primitiveCount() {
        return primitives;
    }

    /**
     * This tree for its primitives renumbered in its leaf order ({@code Mesh.reordered(order)}):
     * the same nodes, without the order.
     */
    public FlatBVH inLeafOrder() {
        return order == null ? this : new FlatBVH(nodes, null, primitives, rootBox, rootLink, rootCount);
    }

    /** The primitive ids in leaf order (not a copy: read only); null when they are numbered so. */
    public int[] leafOrder() {
        return order;
    }

    /** Coordinate k (x0, y0, z0, x1, y1, z1) of the root's box. */
    double rootBound(int k) {
        return rootBox[k];
    }

    /** Depth of the deepest leaf, for statistics. */
    public int depth() {
        return rootCount > 0 ? 1 : 1 + depthBelow(rootLink);
    }

    private int depthBelow(int node) {
        int deepest = 0;
        for (int lane = 0; lane < WideNodes.WIDTH; lane++) {
            int count = nodes.primitiveCount(node, lane);
            if (count != WideNodes.EMPTY) {
                deepest = Math.max(deepest, count > 0 ? 1 : 1 + depthBelow(nodes.link(node, lane)));
            }
        }
        return deepest;
    }

    /** Finds the closest hit before {@code sr.t} among the leaves, recording it in {@code sr}. */
    boolean closestHit(Ray ray, ShadeRec sr, Leaves leaves) {
        return search(root, ray, sr.t, sr, leaves, true);
    }

    /** As {@link #closestHit(Ray, ShadeRec, Leaves)}, searching from {@code start} ({@link #startFor}). */
    boolean closestHit(Start start, Ray ray, ShadeRec sr, Leaves leaves) {
        return search(start, ray, sr.t, sr, leaves, true);
    }

    /** True when some leaf blocks the ray on (0, tMax): for shadow rays, which stop at the first blocker. */
    boolean anyHit(Ray ray, double tMax, ShadeRec sr, Leaves leaves) {
        return search(root, ray, tMax, sr, leaves, false);
    }

    /**
     * The traversal of both searches. From a node, the boxes of its four lanes are tested in one
     * loop ({@link SlabRay#entries}); the ray goes on into the child it enters first and stacks
     * the others it enters, farthest first, until it reaches a leaf or misses every child, and
     * then goes on with the subtree stacked last. The closest-hit search skips a stacked subtree
     * that the ray enters beyond a hit found since; the any-hit search stops at the first leaf that
     * blocks the ray.
     */
    private boolean search(Start start, Ray ray, double tMax, ShadeRec sr, Leaves leaves, boolean closest) {
        TraversalStack.Frame stack = sr.scratch.traversals.push(ray);
        SlabRay slab = stack.ray;
        int[] stackLinks = stack.links;
        int[] stackCounts = stack.counts;
        double[] stackEntries = stack.entries;
        long[] keys = stack.keys;
        float[] bounds = nodes.bounds;
        int[] children = nodes.children;
        double tHit = tMax;
        boolean found = false;
        long boxTests = 1;
        int top = 0;
        double tStart = slab.entry(start.box(), start.at(), tMax);
        if (tStart < tMax) {
            stackLinks[0] = start.link();
            stackCounts[0] = start.count();
            stackEntries[0] = tStart;
            top = 1;
        }
        while (top > 0) {
            top--;
            if (closest && stackEntries[top] >= tHit) {
                continue;
            }
            int link = stackLinks[top];
            int count = stackCounts[top];
            // descend to a leaf, or until the ray misses every child
            while (count == 0) {
                boxTests += WideNodes.WIDTH;
                // the lanes' entries with the lane in their lowest bits: a subtree is then skipped
                // only when the ray enters it beyond the hit, as before (NodeTest)
                TEST.keys(slab, bounds, WideNodes.boxesAt(link), Double.doubleToRawLongBits(tHit), keys);
                long k0 = keys[0];
                long k1 = keys[1];
                long k2 = keys[2];
                long k3 = keys[3];
                // a sorting network of five exchanges, without branches (keys are at most
                // +infinity's bits plus 3, so differences do not overflow)
                long d = k0 - k1;
                d &= d >> 63;
                long a = k1 + d;
                long b = k0 - d;
                d = k2 - k3;
                d &= d >> 63;
                long c = k3 + d;
                long e = k2 - d;
                d = a - c;
                d &= d >> 63;
                long first = c + d;
                a -= d;
                d = b - e;
                d &= d >> 63;
                long last = b - d;
                b = e + d;
                d = a - b;
                d &= d >> 63;
                long second = b + d;
                long third = a - d;
                if (first >= MISS) {
                    break;
                }
                // the ray goes on into the nearest; the others are stacked farthest first, each
                // written and kept only if the ray enters it, without a branch
                int at = WideNodes.linksAt(link);
                top = push(last, at, children, stackLinks, stackCounts, stackEntries, top);
                top = push(third, at, children, stackLinks, stackCounts, stackEntries, top);
                top = push(second, at, children, stackLinks, stackCounts, stackEntries, top);
                int lane = (int) first & 3;
                link = children[at + lane];
                count = children[at + WideNodes.WIDTH + lane];
            }
            if (count > 0) {
                if (closest && leaves.hit(link, count, ray, sr)) {
                    found = true;
                    tHit = sr.t;
                } else if (!closest && leaves.shadowHit(link, count, ray, tMax, sr)) {
                    found = true;
                    break;
                }
            }
        }
        sr.scratch.traversals.pop();
        sr.boxTests += boxTests;
        return found;
    }

    /** The key of a lane the ray misses, +infinity's bits: every lane's key from here up is a miss. */
    private static final long MISS = Double.doubleToRawLongBits(Double.POSITIVE_INFINITY);

    /** Writes the child whose key is {@code key} on top of the stack, and keeps it unless the ray misses it; returns the new top. */
    private static int push(long key, int at, int[] children, int[] links, int[] counts, double[] entries, int top) {
        int lane = (int) key & 3;
        links[top] = children[at + lane];
        counts[top] = children[at + WideNodes.WIDTH + lane];
        entries[top] = Double.longBitsToDouble(key & ~3L);
        return top + (int) ((key - MISS) >>> 63);
    }
}

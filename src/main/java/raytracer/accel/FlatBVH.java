package raytracer.accel;

import java.util.List;
import raytracer.core.ShadeRec;
import raytracer.core.TraversalStack;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Ray;
import raytracer.math.SlabRay;

/**
 * A BVH flattened into arrays, and its traversal (report section 6): the interior nodes in the
 * layout of {@link BvhNodes}, the root apart (its box, and its link and count as a node stores a
 * child's), and the leaf order, which lists the primitives so that every leaf's are one run of it.
 * What a leaf holds and how it is tested is the business of {@link Leaves}. A tree over primitives
 * already renumbered in its leaf order (a mesh's triangles, {@link #inLeafOrder}) keeps no order:
 * it would be 0, 1, 2, ..., four bytes a triangle for nothing.
 */
public final class FlatBVH {
    /** The deepest tree the builders may produce: the depth the traversal stacks have room for. */
    public static final int MAX_DEPTH = TraversalStack.MAX_DEPTH;

    final BvhNodes nodes;
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

    FlatBVH(BvhNodes nodes, int[] order, float[] rootBox, int rootLink, int rootCount) {
        this(nodes, order, order.length, rootBox, rootLink, rootCount);
    }

    /** A tree whose primitives are numbered in its leaf order when {@code order} is null. */
    FlatBVH(BvhNodes nodes, int[] order, int primitives, float[] rootBox, int rootLink, int rootCount) {
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
     * no such ray can reach a leaf: from the root down, as long as the volume wholly excludes one
     * child's box ({@link HalfSpace#excludes}, a margin far above the slab test's rounding). Such
     * a ray misses the excluded box, so from the root it would have tested both boxes of every
     * node above the subtree, stacked nothing, and gone on into the subtree: starting there, it
     * tests the subtree's box, as it did from its parent, and then visits the same nodes in the
     * same order, with the same hits. (Reshetov, Soupikov and Hurley's entry points for the rays
     * of a frustum, "Multi-level ray tracing algorithm", SIGGRAPH 2005, made exact.)
     */
    Start startFor(List<HalfSpace> volume) {
        if (excluded(rootBox, 0, volume)) {
            return null;
        }
        Start start = root;
        while (start.count() == 0) {
            int node = start.link();
            boolean left = !excluded(nodes.bounds, BvhNodes.boxAt(node, BvhNodes.LEFT), volume);
            boolean right = !excluded(nodes.bounds, BvhNodes.boxAt(node, BvhNodes.RIGHT), volume);
            if (left == right) {
                return left ? start : null;
            }
            int side = left ? BvhNodes.LEFT : BvhNodes.RIGHT;
            start = new Start(nodes.bounds, BvhNodes.boxAt(node, side), nodes.link(node, side), nodes.primitiveCount(node, side));
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

    /** All nodes, leaves included (a binary tree has one leaf more than interior nodes). */
    public int nodeCount() {
        return 2 * nodes.count() + 1;
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
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            boolean leaf = nodes.primitiveCount(node, side) > 0;
            deepest = Math.max(deepest, leaf ? 1 : 1 + depthBelow(nodes.link(node, side)));
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
     * The traversal of both searches. From a node, both children's boxes are tested; the ray
     * descends into one it enters and stacks the other if it enters both, until it reaches a leaf
     * or misses both children, and then goes on with the subtree stacked last. For the closest
     * hit it descends into the child it enters first and skips a stacked subtree that it enters
     * beyond a hit found since; for any hit the order does not matter, and the first leaf that
     * blocks the ray ends the search.
     */
    private boolean search(Start start, Ray ray, double tMax, ShadeRec sr, Leaves leaves, boolean closest) {
        TraversalStack.Frame stack = sr.scratch.traversals.push(ray);
        SlabRay slab = stack.ray;
        int[] stackLinks = stack.links;
        int[] stackCounts = stack.counts;
        double[] stackEntries = stack.entries;
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
            // descend to a leaf, or until the ray misses both children
            while (count == 0) {
                // the node's links and counts are read before its boxes are tested, so that the
                // two arrays are fetched together rather than one after the other
                int at = BvhNodes.childAt(link, BvhNodes.LEFT);
                int leftLink = children[at];
                int leftCount = children[at + 1];
                int rightLink = children[at + 2];
                int rightCount = children[at + 3];
                boxTests += 2;
                double tLeft = slab.entry(bounds, BvhNodes.boxAt(link, BvhNodes.LEFT), tHit);
                double tRight = slab.entry(bounds, BvhNodes.boxAt(link, BvhNodes.RIGHT), tHit);
                boolean enterLeft = tLeft < Double.POSITIVE_INFINITY;
                boolean enterRight = tRight < Double.POSITIVE_INFINITY;
                if (enterLeft && enterRight) {
                    // the closest hit goes first into the child the ray enters first, any hit into the left
                    if (closest && tRight < tLeft) {
                        stackLinks[top] = leftLink;
                        stackCounts[top] = leftCount;
                        stackEntries[top++] = tLeft;
                        link = rightLink;
                        count = rightCount;
                    } else {
                        stackLinks[top] = rightLink;
                        stackCounts[top] = rightCount;
                        stackEntries[top++] = tRight;
                        link = leftLink;
                        count = leftCount;
                    }
                } else if (enterLeft) {
                    link = leftLink;
                    count = leftCount;
                } else if (enterRight) {
                    link = rightLink;
                    count = rightCount;
                } else {
                    break;
                }
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
}

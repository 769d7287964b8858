package raytracer.accel;

import raytracer.core.ShadeRec;
import raytracer.core.TraversalStack;
import raytracer.math.Ray;
import raytracer.math.SlabRay;

/**
 * A BVH flattened into arrays, and its traversal (report section 6): the interior nodes in the
 * layout of {@link BvhNodes}, the root apart (its box, and its link and count as a node stores a
 * child's), and the leaf order, which lists the primitives so that every leaf's are one run of it.
 * What a leaf holds and how it is tested is the business of {@link Leaves}.
 */
public final class FlatBVH {
    /** The deepest tree the builders may produce: the depth the traversal stacks have room for. */
    public static final int MAX_DEPTH = TraversalStack.MAX_DEPTH;

    final BvhNodes nodes;
    /** Primitive ids in leaf order: a leaf (link, count) holds order[link .. link + count - 1]. */
    final int[] order;
    final float[] rootBox;
    final int rootLink;
    final int rootCount;

    FlatBVH(BvhNodes nodes, int[] order, float[] rootBox, int rootLink, int rootCount) {
        this.nodes = nodes;
        this.order = order;
        this.rootBox = rootBox;
        this.rootLink = rootLink;
        this.rootCount = rootCount;
    }

    /** All nodes, leaves included (a binary tree has one leaf more than interior nodes). */
    public int nodeCount() {
        return 2 * nodes.count() + 1;
    }

    public int primitiveCount() {
        return order.length;
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
        return search(ray, sr.t, sr, leaves, true);
    }

    /** True when some leaf blocks the ray on (0, tMax): for shadow rays, which stop at the first blocker. */
    boolean anyHit(Ray ray, double tMax, ShadeRec sr, Leaves leaves) {
        return search(ray, tMax, sr, leaves, false);
    }

    /**
     * The traversal of both searches. From a node, both children's boxes are tested; the ray
     * descends into one it enters and stacks the other if it enters both, until it reaches a leaf
     * or misses both children, and then goes on with the subtree stacked last. For the closest
     * hit it descends into the child it enters first and skips a stacked subtree that it enters
     * beyond a hit found since; for any hit the order does not matter, and the first leaf that
     * blocks the ray ends the search.
     */
    private boolean search(Ray ray, double tMax, ShadeRec sr, Leaves leaves, boolean closest) {
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
        double tRoot = slab.entry(rootBox, 0, tMax);
        if (tRoot < tMax) {
            stackLinks[0] = rootLink;
            stackCounts[0] = rootCount;
            stackEntries[0] = tRoot;
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

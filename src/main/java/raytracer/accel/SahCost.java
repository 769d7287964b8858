package raytracer.accel;

/**
 * What a tree is expected to cost a ray, by the surface area heuristic (MacDonald and Booth 1990;
 * pbrt-v4 section 7.3.2): a ray that meets the root's box meets a box inside it with probability
 * the ratio of their surface areas, so the box tests per ray are expected to be the sum over
 * interior nodes of their box tests times their area over the root's, and the primitive tests the
 * sum over leaves of their count times their area over the root's. How trees compare, binary or
 * wide: a wide node tests all its lanes.
 *
 * @param boxTests       expected box tests per ray, the root's own not counted
 * @param primitiveTests expected primitive tests per ray
 */
public record SahCost(double boxTests, double primitiveTests) {
    /** The cost in units of one primitive test, a box test weighing a quarter (the builders' 1/2 per binary node). */
    public double cost() {
        return 0.25 * boxTests + primitiveTests;
    }

    /** Of a builder's binary tree. */
    static SahCost of(BinaryTree tree) {
        if (tree.rootCount() > 0) {
            return new SahCost(0, tree.rootCount());
        }
        double[] sums = new double[2];
        add(tree.nodes(), tree.rootLink(), 1, SahBins.halfArea(tree.rootBox(), 0), sums);
        return new SahCost(sums[0], sums[1]);
    }

    /** Of the tree the renderer searches. */
    public static SahCost of(FlatBVH bvh) {
        if (bvh.rootCount > 0) {
            return new SahCost(0, bvh.rootCount);
        }
        double[] sums = new double[2];
        add(bvh.nodes, bvh.rootLink, 1, SahBins.halfArea(bvh.rootBox, 0), sums);
        return new SahCost(sums[0], sums[1]);
    }

    /** Adds the expected tests below binary node {@code node}, which a ray meets with probability {@code p}. */
    private static void add(BvhNodes nodes, int node, double p, double root, double[] sums) {
        sums[0] += 2 * p;
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            double q = SahBins.halfArea(nodes.bounds, BvhNodes.boxAt(node, side)) / root;
            int count = nodes.primitiveCount(node, side);
            if (count > 0) {
                sums[1] += count * q;
            } else {
                add(nodes, nodes.link(node, side), q, root, sums);
            }
        }
    }

    /** As above, for wide node {@code node}. */
    private static void add(WideNodes nodes, int node, double p, double root, double[] sums) {
        sums[0] += WideNodes.WIDTH * p;
        for (int lane = 0; lane < WideNodes.WIDTH; lane++) {
            int count = nodes.primitiveCount(node, lane);
            if (count == WideNodes.EMPTY) {
                continue;
            }
            double q = SahBins.halfArea(nodes.box(node, lane), 0) / root;
            if (count > 0) {
                sums[1] += count * q;
            } else {
                add(nodes, nodes.link(node, lane), q, root, sums);
            }
        }
    }
}

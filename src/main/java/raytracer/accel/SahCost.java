package raytracer.accel;

/**
 * What a tree is expected to cost a ray, by the surface area heuristic (MacDonald and Booth 1990;
 * pbrt-v4 section 7.3.2): a ray that meets the root's box meets a box inside it with probability
 * the ratio of their surface areas, so the box tests per ray are expected to be the sum over
 * interior nodes of their two box tests times their area over the root's, and the primitive tests
 * the sum over leaves of their count times their area over the root's. How trees compare.
 *
 * @param boxTests       expected box tests per ray, the root's own not counted
 * @param primitiveTests expected primitive tests per ray
 */
public record SahCost(double boxTests, double primitiveTests) {
    /** The cost in units of one primitive test, a box test weighing a quarter (the builders' 1/2 per node visit). */
    public double cost() {
        return 0.25 * boxTests + primitiveTests;
    }

    public static SahCost of(FlatBVH bvh) {
        return of(bvh.nodes, bvh.rootBox, bvh.rootLink, bvh.rootCount);
    }

    static SahCost of(BinaryTree tree) {
        return of(tree.nodes(), tree.rootBox(), tree.rootLink(), tree.rootCount());
    }

    private static SahCost of(BvhNodes nodes, float[] rootBox, int rootLink, int rootCount) {
        if (rootCount > 0) {
            return new SahCost(0, rootCount);
        }
        double[] sums = new double[2];
        add(nodes, rootLink, 1, SahBins.halfArea(rootBox, 0), sums);
        return new SahCost(sums[0], sums[1]);
    }

    /** Adds the expected tests below {@code node}, which a ray meets with probability {@code p}. */
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
}

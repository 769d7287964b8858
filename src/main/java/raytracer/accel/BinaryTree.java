package raytracer.accel;

/**
 * A builder's binary tree, as the report's BVH is drawn: its interior nodes ({@link BvhNodes}),
 * its leaf order, and its root apart (box, link and count as a node stores a child). The
 * renderer searches it {@link #collapsed} into four-wide nodes; the builders' tests and the
 * surface area figures read it as built.
 */
record BinaryTree(BvhNodes nodes, int[] order, float[] rootBox, int rootLink, int rootCount) {
    /** The tree the renderer searches: the same leaves under four-wide nodes ({@link WideCollapse}). */
    FlatBVH collapsed() {
        WideNodes wide = rootCount > 0 ? new WideNodes(0) : WideCollapse.collapse(nodes, rootLink);
        return new FlatBVH(wide, order, order.length, rootBox, rootCount > 0 ? rootLink : 0, rootCount);
    }
}

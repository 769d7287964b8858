package raytracer.accel;

/**
 * A builder's tree, as the report's BVH is drawn: its interior nodes ({@link BvhNodes}), its leaf
 * order, and its root apart (box, link and count as a node stores a child). The median builders
 * number the nodes depth-first, a node, its left subtree, its right subtree, using every number;
 * the SAH builder reserves numbers for subtrees before it knows their sizes and leaves some
 * unused. {@link #flat} packs the nodes into that depth-first numbering, without gaps, for the
 * renderer and the mesh cache.
 */
record BinaryTree(BvhNodes nodes, int[] order, float[] rootBox, int rootLink, int rootCount) {
    /** The tree the renderer searches: the same nodes, numbered depth-first without gaps. */
    FlatBVH flat() {
        if (rootCount > 0) {
            return new FlatBVH(new BvhNodes(0), order, rootBox, rootLink, rootCount);
        }
        int used = countBelow(rootLink);
        if (used == nodes.count() && numberedDepthFirst(rootLink, 0) == used) {
            return new FlatBVH(nodes, order, rootBox, 0, 0);
        }
        BvhNodes packed = new BvhNodes(used);
        copy(rootLink, packed, new int[1]);
        return new FlatBVH(packed, order, rootBox, 0, 0);
    }

    /** Interior nodes in the subtree of {@code node}, itself included. */
    private int countBelow(int node) {
        int count = 1;
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            if (nodes.primitiveCount(node, side) == 0) {
                count += countBelow(nodes.link(node, side));
            }
        }
        return count;
    }

    /** The number after the subtree of {@code node} if it is numbered depth-first from {@code expected}, else -1. */
    private int numberedDepthFirst(int node, int expected) {
        if (node != expected) {
            return -1;
        }
        int next = node + 1;
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT && next >= 0; side++) {
            if (nodes.primitiveCount(node, side) == 0) {
                next = numberedDepthFirst(nodes.link(node, side), next);
            }
        }
        return next;
    }

    /** Copies the subtree of {@code node} into {@code to} from number {@code next[0]} on; returns its number there. */
    private int copy(int node, BvhNodes to, int[] next) {
        int mine = next[0]++;
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            to.setBox(mine, side, nodes.bounds, BvhNodes.boxAt(node, side));
            int count = nodes.primitiveCount(node, side);
            if (count > 0) {
                to.setLeaf(mine, side, nodes.link(node, side), count);
            } else {
                to.setInterior(mine, side, copy(nodes.link(node, side), to, next));
            }
        }
        return mine;
    }
}

package raytracer.accel;

/**
 * The interior nodes of a flattened BVH, numbered in depth-first order, in two arrays. A node holds
 * its two children, so that the traversal tests both from one place:
 *
 * <pre>
 *   bounds[12 n .. 12 n + 6)        the left child's box:  x0, y0, z0, x1, y1, z1
 *   bounds[12 n + 6 .. 12 n + 12)   the right child's box
 *   children[4 n], children[4 n + 1]       the left child's link and count
 *   children[4 n + 2], children[4 n + 3]   the right child's link and count
 * </pre>
 *
 * Boxes are floats rounded outward, so a box never shrinks: half the memory of doubles, and a
 * visit reads 64 bytes. A child with count 0 is an interior node whose number is its link; a leaf
 * has a count above 0 and links to its first primitive in the tree's leaf order, so that its
 * primitives are entries link .. link + count - 1 of that order.
 */
final class BvhNodes {
    static final int LEFT = 0;
    static final int RIGHT = 1;
    /** Floats of a box, and of a node's two boxes. */
    static final int BOX = 6;
    static final int BOUNDS_PER_NODE = 2 * BOX;
    static final int CHILDREN_PER_NODE = 4;

    final float[] bounds;
    final int[] children;

    BvhNodes(int count) {
        bounds = new float[BOUNDS_PER_NODE * count];
        children = new int[CHILDREN_PER_NODE * count];
    }

    int count() {
        return children.length / CHILDREN_PER_NODE;
    }

    /** Where the box of {@code node}'s child on {@code side} starts in {@link #bounds}. */
    static int boxAt(int node, int side) {
        return BOUNDS_PER_NODE * node + BOX * side;
    }

    /** Where the link of {@code node}'s child on {@code side} is in {@link #children}; its count follows. */
    static int childAt(int node, int side) {
        return CHILDREN_PER_NODE * node + 2 * side;
    }

    void setBox(int node, int side, float[] box, int at) {
        System.arraycopy(box, at, bounds, boxAt(node, side), BOX);
    }

    /** Makes {@code node}'s child on {@code side} the interior node {@code child}. */
    void setInterior(int node, int side, int child) {
        children[childAt(node, side)] = child;
        children[childAt(node, side) + 1] = 0;
    }

    /** Makes {@code node}'s child on {@code side} the leaf of primitives first .. first + count - 1. */
    void setLeaf(int node, int side, int first, int count) {
        children[childAt(node, side)] = first;
        children[childAt(node, side) + 1] = count;
    }

    int link(int node, int side) {
        return children[childAt(node, side)];
    }

    int primitiveCount(int node, int side) {
        return children[childAt(node, side) + 1];
    }
}

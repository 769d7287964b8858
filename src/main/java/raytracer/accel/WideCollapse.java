package raytracer.accel;

/**
 * A binary BVH collapsed into a 4-wide one ({@link WideNodes}), as Embree makes its BVH4 from a
 * binary build and pbrt-v4 discusses (section 7.3.4, "wider BVHs"): a wide node starts from a
 * binary node's two children and, while it has fewer than four, replaces the interior child of
 * largest surface area (the one a ray most likely enters) by that child's two children, in place,
 * so the lanes keep the binary tree's left-to-right order. The leaves, their boxes and the leaf
 * order are the binary tree's; only interior boxes that a wide node skips are dropped. Nodes are
 * numbered depth-first, a node before its children, so the same binary tree always gives the same
 * arrays.
 */
final class WideCollapse {
    private final BvhNodes binary;
    private final WideNodes wide;
    private int size;
    /** Per recursion depth, the (binary node, side) of the lanes being gathered. */
    private final int[] parents = new int[WideNodes.WIDTH * (FlatBVH.MAX_DEPTH + 1)];
    private final int[] sides = new int[WideNodes.WIDTH * (FlatBVH.MAX_DEPTH + 1)];

    private WideCollapse(BvhNodes binary) {
        this.binary = binary;
        // each wide node takes at least one binary interior node
        this.wide = new WideNodes(binary.count());
    }

    /** The wide nodes of the binary tree under interior node {@code root}; the root's wide node is node 0. */
    static WideNodes collapse(BvhNodes binary, int root) {
        WideCollapse c = new WideCollapse(binary);
        c.node(root, 0);
        return c.wide.first(c.size);
    }

    /** Makes the wide node of binary interior node {@code b}, at recursion depth {@code depth}; returns its number. */
    private int node(int b, int depth) {
        int w = size++;
        int at = WideNodes.WIDTH * depth;
        parents[at] = b;
        sides[at] = BvhNodes.LEFT;
        parents[at + 1] = b;
        sides[at + 1] = BvhNodes.RIGHT;
        int lanes = 2;
        while (lanes < WideNodes.WIDTH) {
            int open = -1;
            double largest = -1;
            for (int i = 0; i < lanes; i++) {
                if (binary.primitiveCount(parents[at + i], sides[at + i]) == 0) {
                    double area = SahBins.halfArea(binary.bounds, BvhNodes.boxAt(parents[at + i], sides[at + i]));
                    if (area > largest) {
                        largest = area;
                        open = i;
                    }
                }
            }
            if (open < 0) {
                break;
            }
            int child = binary.link(parents[at + open], sides[at + open]);
            for (int i = lanes; i > open + 1; i--) {
                parents[at + i] = parents[at + i - 1];
                sides[at + i] = sides[at + i - 1];
            }
            parents[at + open] = child;
            sides[at + open] = BvhNodes.LEFT;
            parents[at + open + 1] = child;
            sides[at + open + 1] = BvhNodes.RIGHT;
            lanes++;
        }
        for (int i = 0; i < WideNodes.WIDTH; i++) {
            if (i >= lanes) {
                wide.setEmpty(w, i);
                continue;
            }
            int parent = parents[at + i];
            int side = sides[at + i];
            int count = binary.primitiveCount(parent, side);
            int link = count > 0 ? binary.link(parent, side) : node(binary.link(parent, side), depth + 1);
            wide.set(w, i, binary.bounds, BvhNodes.boxAt(parent, side), link, count);
        }
        return w;
    }
}

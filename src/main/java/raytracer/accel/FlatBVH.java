package raytracer.accel;

import raytracer.core.ShadeRec;
import raytracer.math.Ray;
import raytracer.math.Slabs;

/**
 * A BVH flattened into arrays in depth-first order, as pbrt stores it: node i's left child is
 * i + 1; {@code meta[2i]} is the right child (interior) or the first entry in {@code order} (leaf),
 * and {@code meta[2i + 1]} is -(split axis + 1) for an interior node or the primitive count of a leaf.
 * Bounds are doubles, exactly the union of the primitives' own bounds.
 */
public final class FlatBVH {
    /** Deepest tree the builders produce; traversal stacks are this big. */
    public static final int MAX_DEPTH = 64;

    final double[] bounds;
    final int[] meta;
    final int[] order;
    final int nodeCount;

    FlatBVH(double[] bounds, int[] meta, int[] order, int nodeCount) {
        this.bounds = bounds;
        this.meta = meta;
        this.order = order;
        this.nodeCount = nodeCount;
    }

    public int nodeCount() {
        return nodeCount;
    }

    public int primitiveCount() {
        return order.length;
    }

    boolean isLeaf(int node) {
        return meta[2 * node + 1] > 0;
    }

    /** Depth of the deepest leaf, for statistics. */
    public int depth() {
        return depth(0);
    }

    private int depth(int node) {
        return isLeaf(node) ? 1 : 1 + Math.max(depth(node + 1), depth(meta[2 * node]));
    }

    /** Conservative slab test of a node on (0, tMax), counted for statistics. */
    boolean slab(int node, Ray ray, double tMax, ShadeRec sr) {
        sr.boxTests++;
        return Slabs.overlap(bounds, 6 * node, ray, tMax);
    }
}

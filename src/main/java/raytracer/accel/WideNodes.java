package raytracer.accel;

import java.util.Arrays;

/**
 * The nodes of a 4-wide BVH (Embree's BVH4; Wald, Benthin and Boulos, "Getting rid of packets",
 * 2008), numbered in depth-first order, in two arrays. A node holds up to four children, their
 * boxes stored plane by plane, so that one loop over the four lanes tests them all:
 *
 * <pre>
 *   bounds[24 n .. 24 n + 4)        x0 of children 0..3
 *   bounds[24 n + 4 .. 24 n + 8)    y0 of children 0..3,  then z0, x1, y1, z1, four each
 *   children[8 n + i]               child i's link
 *   children[8 n + 4 + i]           child i's primitive count
 * </pre>
 *
 * As in {@link BvhNodes}, a child with count 0 is an interior node whose number is its link, and
 * a leaf has a count above 0 and links to its first primitive in the leaf order. A lane without a
 * child has count {@link #EMPTY} and the empty box (+infinity, -infinity on every axis), which no
 * slab test enters. Boxes are floats rounded outward, as the binary tree's: a visit reads 96 bytes
 * of boxes and 32 of links.
 */
final class WideNodes {
    static final int WIDTH = 4;
    static final int BOUNDS_PER_NODE = 6 * WIDTH;
    static final int CHILDREN_PER_NODE = 2 * WIDTH;
    /** The count of a lane without a child. */
    static final int EMPTY = -1;

    final float[] bounds;
    final int[] children;

    WideNodes(int count) {
        this(new float[BOUNDS_PER_NODE * count], new int[CHILDREN_PER_NODE * count]);
    }

    WideNodes(float[] bounds, int[] children) {
        this.bounds = bounds;
        this.children = children;
    }

    int count() {
        return children.length / CHILDREN_PER_NODE;
    }

    /** The first nodes only: a builder's arrays, sized for the most nodes it might make, trimmed to those it made. */
    WideNodes first(int count) {
        return new WideNodes(Arrays.copyOf(bounds, BOUNDS_PER_NODE * count), Arrays.copyOf(children, CHILDREN_PER_NODE * count));
    }

    /** Where the boxes of {@code node}'s children start in {@link #bounds}. */
    static int boxesAt(int node) {
        return BOUNDS_PER_NODE * node;
    }

    /** Where {@code node}'s links start in {@link #children}; the counts follow, {@link #WIDTH} on. */
    static int linksAt(int node) {
        return CHILDREN_PER_NODE * node;
    }

    int link(int node, int lane) {
        return children[linksAt(node) + lane];
    }

    int primitiveCount(int node, int lane) {
        return children[linksAt(node) + WIDTH + lane];
    }

    /** Coordinate k (x0, y0, z0, x1, y1, z1) of the box of {@code node}'s child in {@code lane}. */
    float bound(int node, int lane, int k) {
        return bounds[boxesAt(node) + WIDTH * k + lane];
    }

    /** The box of {@code node}'s child in {@code lane}, as six floats x0, y0, z0, x1, y1, z1. */
    float[] box(int node, int lane) {
        float[] box = new float[6];
        for (int k = 0; k < 6; k++) {
            box[k] = bound(node, lane, k);
        }
        return box;
    }

    /** Makes {@code lane} of {@code node} the child with the box {@code box[at .. at + 6)}, link and count. */
    void set(int node, int lane, float[] box, int at, int link, int count) {
        for (int k = 0; k < 6; k++) {
            bounds[boxesAt(node) + WIDTH * k + lane] = box[at + k];
        }
        children[linksAt(node) + lane] = link;
        children[linksAt(node) + WIDTH + lane] = count;
    }

    /** Makes {@code lane} of {@code node} empty. */
    void setEmpty(int node, int lane) {
        for (int k = 0; k < 3; k++) {
            bounds[boxesAt(node) + WIDTH * k + lane] = Float.POSITIVE_INFINITY;
            bounds[boxesAt(node) + WIDTH * (k + 3) + lane] = Float.NEGATIVE_INFINITY;
        }
        children[linksAt(node) + lane] = 0;
        children[linksAt(node) + WIDTH + lane] = EMPTY;
    }
}

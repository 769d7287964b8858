package raytracer.accel;

import java.util.Arrays;
import java.util.Comparator;

/**
 * The report's BVH (section 6) built as the report states it: a node with more primitives than a
 * leaf holds sorts them by the centroids of their boxes along the longest axis of its own box and
 * splits them at the median, the first half (the smaller one when the count is odd) to the left
 * child. Equal centroids are ordered by primitive id, so the order is total and the tree unique.
 *
 * <p>Sorting at every level costs O(n log^2 n). {@link MedianSplitBuilder} builds the same tree,
 * node for node and in the same leaf order (SortedMedianBuilderTest), in O(n log n) by selecting
 * the median instead, and is the one the renderer uses; this one is the reference it is checked
 * against, and the place to start reading.
 */
public final class SortedMedianBuilder {
    private final int leafSize;

    public SortedMedianBuilder(int leafSize) {
        if (leafSize < 1) {
            throw new IllegalArgumentException("leaf size must be at least 1, got " + leafSize);
        }
        this.leafSize = leafSize;
    }

    /** Builds over primitives whose boxes are {@code primBounds[6i .. 6i+6)} = (x0, y0, z0, x1, y1, z1). */
    public FlatBVH build(double[] primBounds) {
        return build(FloatBoxes.roundOutward(primBounds));
    }

    /** Builds over primitives whose boxes are the floats {@code boxes[6i .. 6i+6)}, rounded outward. */
    public FlatBVH build(float[] boxes) {
        return binary(boxes).flat();
    }

    /** The binary tree that {@link #build(float[])} flattens: the same nodes, numbered depth-first. */
    BinaryTree binary(float[] boxes) {
        int n = boxes.length / 6;
        if (n == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        Integer[] ids = new Integer[n];
        for (int i = 0; i < n; i++) {
            ids[i] = i;
        }
        DepthFirstTree tree = new DepthFirstTree();
        split(boxes, ids, 0, n, tree);
        return tree.flatten(Arrays.stream(ids).mapToInt(Integer::intValue).toArray());
    }

    /** Adds the node over the primitives ids[from .. to - 1] and, unless it is a leaf, its subtree. */
    private void split(float[] boxes, Integer[] ids, int from, int to, DepthFirstTree tree) {
        float[] box = bounds(boxes, ids, from, to);
        int node = tree.add(toDoubles(box), 0);
        if (to - from <= leafSize) {
            tree.setLeaf(node, from, to - from);
            return;
        }
        int axis = FloatBoxes.longestAxis(box, 0);
        Arrays.sort(ids, from, to, byCentroid(boxes, axis));
        int mid = from + (to - from) / 2;
        split(boxes, ids, from, mid, tree);
        int right = tree.size();
        split(boxes, ids, mid, to, tree);
        tree.setInterior(node, right);
    }

    /** By the centroid on the axis, then by id. */
    private static Comparator<Integer> byCentroid(float[] boxes, int axis) {
        return (a, b) -> {
            float keyA = FloatBoxes.centroidKey(boxes, a, axis);
            float keyB = FloatBoxes.centroidKey(boxes, b, axis);
            return keyA < keyB ? -1 : keyA > keyB ? 1 : Integer.compare(a, b);
        };
    }

    /** The smallest box around the primitives ids[from .. to - 1]. */
    private static float[] bounds(float[] boxes, Integer[] ids, int from, int to) {
        float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                       Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int i = from; i < to; i++) {
            int p = 6 * ids[i];
            for (int k = 0; k < 3; k++) {
                box[k] = Math.min(box[k], boxes[p + k]);
                box[3 + k] = Math.max(box[3 + k], boxes[p + 3 + k]);
            }
        }
        return box;
    }

    private static double[] toDoubles(float[] box) {
        double[] d = new double[box.length];
        for (int k = 0; k < box.length; k++) {
            d[k] = box[k];
        }
        return d;
    }
}

package raytracer.accel;

/**
 * The bins of one node in a binned SAH build (Wald, "On fast construction of SAH-based bounding
 * volume hierarchies", 2007; pbrt-v4 section 7.3.2): the node's primitives are dropped by
 * centroid into equal slices of its box along the box's longest axis, each bin keeping its count
 * and the union of its boxes; a sweep over the bins then finds the plane between two bins of
 * least cost N_L A_L + N_R A_R (A the half surface area). Centroids are the builders' keys
 * ({@link FloatBoxes#centroidKey}, twice the centroid), so a primitive's bin is computed the same
 * way, from the same floats, when it is binned and when it is partitioned ({@link #bin}).
 *
 * <p>The slices divide the node's box, not the box of its centroids as in pbrt-v4 and Wald's paper:
 * that one is known only after a pass over the primitives, the node's box before it, so a node's
 * partition can bin each primitive for the child it goes to as it places it, and a level of the
 * tree costs one pass over its primitives instead of two. The dragon's tree costs 1.5% more by the
 * SAH for it, the bunny's the same; the build takes about a tenth less time
 * (tools/studies/bvh/README.md).
 */
final class SahBins {
    /**
     * Bins for a node of at least as many primitives (a smaller node has one per primitive):
     * pbrt-v4 uses 12, Wald 16 to 32. On the dragon 12, 16 and 32 gave trees within 1% of one
     * another by SAH cost (31.6, 31.4, 31.2). One axis, as pbrt-v4: binning all three made trees
     * 3% cheaper for 1.8 times the build.
     */
    static final int BINS = 16;

    private final int[] counts = new int[BINS];
    private final float[] boxes = new float[6 * BINS];
    private final double[] rightAreas = new double[BINS];
    private final int[] rightCounts = new int[BINS];
    /** A box being grown by the sweep. */
    private final float[] acc = new float[6];
    /** What {@link #prepare} set: the axis, the bins in use, the key where bin 0 starts and the bins per unit of key. */
    private int axis;
    private int used;
    private float low;
    private float scale;
    /** The best plane of the last {@link #sweep}: after bin {@link #bestBin}, with {@link #leftCount} primitives before it. */
    int bestBin;
    int leftCount;

    /** The bin of a centroid key, binned from {@code low} at {@code scale} bins per unit, of bins 0 .. last. */
    static int bin(float key, float low, float scale, int last) {
        // key - low >= 0 exactly (no key is below low); the product may reach the bin count at
        // the top, and (int) of it is clamped here
        return Math.min((int) ((key - low) * scale), last);
    }

    int lastBin() {
        return used - 1;
    }

    /**
     * Empties the bins for a node of {@code count} primitives in the box {@code box[at .. at + 6)};
     * false when the box has no extent along its longest axis, so nothing can be binned.
     */
    boolean prepare(float[] box, int at, int count) {
        axis = FloatBoxes.longestAxis(box, at);
        used = Math.min(BINS, Math.max(2, count));
        // a primitive in the box has a key lo + hi within twice the box's planes, exactly
        low = 2 * box[at + axis];
        float extent = 2 * box[at + 3 + axis] - low;
        // slightly fewer bins than `used` per extent, so that the top key falls in the last bin rather than past it
        scale = used * 0.99999f / extent;
        for (int b = 0; b < used; b++) {
            counts[b] = 0;
            empty(boxes, 6 * b);
        }
        return extent > 0;
    }

    /** Bins primitives from .. to - 1 of {@code prims} (boxes, six floats each). */
    void fill(float[] prims, int from, int to) {
        for (int q = 6 * from; q < 6 * to; q += 6) {
            add(prims, q);
        }
    }

    /** Drops the primitive whose box is {@code prims[q .. q + 6)} into its bin. */
    private void add(float[] prims, int q) {
        int b = bin(prims[q + axis] + prims[q + 3 + axis], low, scale, used - 1);
        counts[b]++;
        int r = 6 * b;
        // a bin's box rarely grows once it holds a few boxes: a store only when it does, so that
        // consecutive boxes in one bin do not wait on each other's stores
        float v = prims[q];
        if (v < boxes[r]) {
            boxes[r] = v;
        }
        v = prims[q + 1];
        if (v < boxes[r + 1]) {
            boxes[r + 1] = v;
        }
        v = prims[q + 2];
        if (v < boxes[r + 2]) {
            boxes[r + 2] = v;
        }
        v = prims[q + 3];
        if (v > boxes[r + 3]) {
            boxes[r + 3] = v;
        }
        v = prims[q + 4];
        if (v > boxes[r + 4]) {
            boxes[r + 4] = v;
        }
        v = prims[q + 5];
        if (v > boxes[r + 5]) {
            boxes[r + 5] = v;
        }
    }

    /** Finds the cheapest plane between the bins; false when every primitive fell in one bin. Ties go to the lower bin. */
    boolean sweep() {
        double bestCost = Double.POSITIVE_INFINITY;
        bestBin = -1;
        // from the right: the area and count right of each plane
        empty(acc, 0);
        int right = 0;
        for (int b = used - 1; b > 0; b--) {
            if (counts[b] > 0) {
                grow(6 * b);
                right += counts[b];
            }
            rightCounts[b] = right;
            rightAreas[b] = right == 0 ? 0 : halfArea(acc, 0);
        }
        empty(acc, 0);
        int left = 0;
        for (int b = 0; b < used - 1; b++) {
            if (counts[b] > 0) {
                grow(6 * b);
                left += counts[b];
            }
            if (left == 0 || rightCounts[b + 1] == 0) {
                continue;
            }
            double cost = left * halfArea(acc, 0) + rightCounts[b + 1] * rightAreas[b + 1];
            if (cost < bestCost) {
                bestCost = cost;
                bestBin = b;
                leftCount = left;
            }
        }
        return bestBin >= 0;
    }

    /** The union of the boxes in bins from .. to - 1, written to {@code out[at .. at + 6)}. */
    void union(int from, int to, float[] out, int at) {
        empty(acc, 0);
        for (int b = from; b < to; b++) {
            if (counts[b] > 0) {
                grow(6 * b);
            }
        }
        System.arraycopy(acc, 0, out, at, 6);
    }

    /**
     * Moves primitives from .. to - 1 whose centroids fall in bins up to {@link #bestBin} before the
     * others, their boxes, ids and carried ints together ({@link BoxSelect#swap}), and returns where
     * the others start. Each primitive is binned for its part as its place is settled, into
     * {@code left} or {@code right} (prepared for the children; null: not binned).
     */
    int partition(float[] p, int[] ids, int[] carried, int from, int to, SahBins left, SahBins right) {
        int last = used - 1;
        int i = from;
        int j = to - 1;
        for (;;) {
            // past the primitives at the front that stay there
            while (i <= j && bin(p[6 * i + axis] + p[6 * i + 3 + axis], low, scale, last) <= bestBin) {
                if (left != null) {
                    left.add(p, 6 * i);
                }
                i++;
            }
            // and past those at the back
            while (i <= j && bin(p[6 * j + axis] + p[6 * j + 3 + axis], low, scale, last) > bestBin) {
                if (right != null) {
                    right.add(p, 6 * j);
                }
                j--;
            }
            if (i >= j) {
                return i;
            }
            // each in the other's part: exchanged, both are binned on the next scans
            BoxSelect.swap(p, ids, carried, i, j);
        }
    }

    private static void empty(float[] box, int at) {
        box[at] = Float.POSITIVE_INFINITY;
        box[at + 1] = Float.POSITIVE_INFINITY;
        box[at + 2] = Float.POSITIVE_INFINITY;
        box[at + 3] = Float.NEGATIVE_INFINITY;
        box[at + 4] = Float.NEGATIVE_INFINITY;
        box[at + 5] = Float.NEGATIVE_INFINITY;
    }

    private void grow(int q) {
        for (int k = 0; k < 3; k++) {
            acc[k] = Math.min(acc[k], boxes[q + k]);
            acc[3 + k] = Math.max(acc[3 + k], boxes[q + 3 + k]);
        }
    }

    /** Half the surface area of the box {@code b[at .. at + 6)}, in doubles: the SAH's A up to a constant factor. */
    static double halfArea(float[] b, int at) {
        double ex = (double) b[at + 3] - b[at];
        double ey = (double) b[at + 4] - b[at + 1];
        double ez = (double) b[at + 5] - b[at + 2];
        return ex * ey + ey * ez + ez * ex;
    }
}

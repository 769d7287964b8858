package raytracer.accel;

import java.util.Arrays;

/**
 * The bins of a binned SAH build (Wald, "On fast construction of SAH-based bounding volume
 * hierarchies", 2007; pbrt-v4 section 7.3.2), one set per builder task: a node's primitives are
 * dropped by centroid into equal slices of its centroids' extent along the axis where they spread
 * most, each bin keeping its count and the union of its boxes; a sweep over the bins then finds
 * the plane between two bins of least cost N_L A_L + N_R A_R (A the half surface area).
 * Centroids are the builders' keys ({@link FloatBoxes#centroidKey}, twice the centroid), so a
 * primitive's bin is computed the same way, from the same floats, when it is binned and when it is
 * partitioned ({@link #bin}).
 */
final class SahBins {
    /**
     * Bins for a node of at least as many primitives (a smaller node has one per primitive):
     * pbrt-v4 uses 12, Wald 16 to 32. On the dragon 12, 16 and 32 gave trees within 1% of one
     * another by SAH cost (31.6, 31.4, 31.2). One axis, as pbrt-v4: binning all three made trees
     * 3% cheaper (27.6 against 28.4, leaves split while the SAH says so) for 1.8 times the build.
     */
    static final int BINS = 16;

    private final int[] counts = new int[BINS];
    private final float[] boxes = new float[6 * BINS];
    private final double[] rightAreas = new double[BINS];
    private final int[] rightCounts = new int[BINS];
    /** A box being grown by the sweep. */
    private final float[] acc = new float[6];
    /** The last {@link #fill}'s axis, bins, where its centroids start and its bins per unit of key. */
    private int axis;
    private int used;
    private float low;
    private float scale;
    /** The best plane of the last {@link #sweep}: after bin {@link #bestBin}, at cost {@link #bestCost}. */
    int bestBin;
    double bestCost;

    /** The bin of a centroid key, binned from {@code low} at {@code scale} bins per unit, of bins 0 .. last. */
    static int bin(float key, float low, float scale, int last) {
        // key - low >= 0 exactly (low is the least key); the product may reach the bin count at
        // the top, and (int) of it is clamped here
        return Math.min((int) ((key - low) * scale), last);
    }

    int axis() {
        return axis;
    }

    float low() {
        return low;
    }

    float scale() {
        return scale;
    }

    int lastBin() {
        return used - 1;
    }

    /**
     * Bins primitives from .. to - 1 of {@code prims} (boxes, six floats each) whose centroid keys
     * lie in the box {@code centroids[at .. at + 6)}; false, and nothing binned, when the keys
     * do not spread on any axis.
     */
    boolean fill(float[] prims, int from, int to, float[] centroids, int at) {
        axis = FloatBoxes.longestAxis(centroids, at);
        used = Math.min(BINS, Math.max(2, to - from));
        low = centroids[at + axis];
        float extent = centroids[at + 3 + axis] - low;
        if (!(extent > 0)) {
            return false;
        }
        // slightly fewer bins than `used` per extent, so that the top key falls in the last bin rather than past it
        scale = used * 0.99999f / extent;
        Arrays.fill(counts, 0, used, 0);
        for (int b = 0; b < used; b++) {
            empty(boxes, 6 * b);
        }
        int last = used - 1;
        for (int p = 6 * from; p < 6 * to; p += 6) {
            int b = bin(prims[p + axis] + prims[p + 3 + axis], low, scale, last);
            counts[b]++;
            int q = 6 * b;
            // comparisons rather than Math.min/max, as in FloatBoxes.union
            float v = prims[p];
            boxes[q] = v < boxes[q] ? v : boxes[q];
            v = prims[p + 1];
            boxes[q + 1] = v < boxes[q + 1] ? v : boxes[q + 1];
            v = prims[p + 2];
            boxes[q + 2] = v < boxes[q + 2] ? v : boxes[q + 2];
            v = prims[p + 3];
            boxes[q + 3] = v > boxes[q + 3] ? v : boxes[q + 3];
            v = prims[p + 4];
            boxes[q + 4] = v > boxes[q + 4] ? v : boxes[q + 4];
            v = prims[p + 5];
            boxes[q + 5] = v > boxes[q + 5] ? v : boxes[q + 5];
        }
        return true;
    }

    /** Finds the cheapest plane between the bins of the last {@link #fill}; false when every primitive fell in one bin. Ties go to the lower bin. */
    boolean sweep() {
        bestCost = Double.POSITIVE_INFINITY;
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

    private static void empty(float[] box, int at) {
        Arrays.fill(box, at, at + 3, Float.POSITIVE_INFINITY);
        Arrays.fill(box, at + 3, at + 6, Float.NEGATIVE_INFINITY);
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

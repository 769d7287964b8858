package raytracer.accel;

import java.util.Arrays;

/**
 * A BVH built by the surface area heuristic with binning (Wald, "On fast construction of SAH-based
 * bounding volume hierarchies", 2007): centroids are dropped into {@value #BINS} bins per axis and
 * the split minimising C = C_trav + (N_L A_L + N_R A_R) / A is taken, or a leaf when that costs
 * more than intersecting everything. The renderer's SAH builder until the parallel one of the same name
 * ({@link SahBuilder}) replaced it; kept here for BvhStudy's comparison.
 */
public final class SerialSahBuilder {
    private static final int BINS = 16;
    /** Cost of one node visit relative to one primitive test. */
    private static final double TRAVERSAL_COST = 0.5;

    private final int maxLeafSize;

    public SerialSahBuilder(int maxLeafSize) {
        if (maxLeafSize < 1) {
            throw new IllegalArgumentException("leaf size must be at least 1, got " + maxLeafSize);
        }
        this.maxLeafSize = maxLeafSize;
    }

    public FlatBVH build(double[] primBounds) {
        return binary(primBounds).flat();
    }

    /** The binary tree that {@link #build} collapses into wide nodes. */
    BinaryTree binary(double[] primBounds) {
        int n = primBounds.length / 6;
        if (n == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        State s = new State(primBounds, n);
        buildNode(s, 0, n, 1);
        return s.tree.flatten(s.order);
    }

    /** Build-time arrays, and the tree as it grows. */
    private static final class State {
        final double[] primBounds;
        final double[] centroids;
        final int[] order;
        final DepthFirstTree tree = new DepthFirstTree();
        final int[] binCount = new int[BINS];
        final double[] binBounds = new double[6 * BINS];
        final double[] rightArea = new double[BINS];

        State(double[] primBounds, int n) {
            this.primBounds = primBounds;
            centroids = new double[3 * n];
            order = new int[n];
            for (int i = 0; i < n; i++) {
                order[i] = i;
                for (int k = 0; k < 3; k++) {
                    centroids[3 * i + k] = 0.5 * (primBounds[6 * i + k] + primBounds[6 * i + 3 + k]);
                }
            }
        }
    }

    private void buildNode(State s, int from, int to, int depth) {
        int count = to - from;
        double[] box = unionBounds(s, from, to);
        int node = s.tree.add(box, 0);
        double[] cbox = centroidBounds(s, from, to);
        int bestAxis = -1;
        int bestBin = -1;
        double bestCost = Double.POSITIVE_INFINITY;
        double area = surfaceArea(box, 0);
        for (int axis = 0; axis < 3 && count > 1; axis++) {
            double lo = cbox[axis];
            double extent = cbox[axis + 3] - lo;
            if (!(extent > 0)) {
                continue;
            }
            Arrays.fill(s.binCount, 0);
            for (int b = 0; b < BINS; b++) {
                resetBox(s.binBounds, 6 * b);
            }
            for (int i = from; i < to; i++) {
                int b = bin(s.centroids[3 * s.order[i] + axis], lo, extent);
                s.binCount[b]++;
                grow(s.binBounds, 6 * b, s.primBounds, 6 * s.order[i]);
            }
            // sweep from the right to know the area right of each split, then from the left
            double[] acc = new double[6];
            resetBox(acc, 0);
            for (int b = BINS - 1; b > 0; b--) {
                grow(acc, 0, s.binBounds, 6 * b);
                s.rightArea[b] = surfaceArea(acc, 0);
            }
            resetBox(acc, 0);
            int leftCount = 0;
            for (int b = 0; b < BINS - 1; b++) {
                grow(acc, 0, s.binBounds, 6 * b);
                leftCount += s.binCount[b];
                int rightCount = count - leftCount;
                if (leftCount == 0 || rightCount == 0) {
                    continue;
                }
                double cost = TRAVERSAL_COST + (leftCount * surfaceArea(acc, 0) + rightCount * s.rightArea[b + 1]) / area;
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
        boolean leafIsCheaper = bestCost >= count && count <= maxLeafSize;
        if (count == 1 || leafIsCheaper || depth >= FlatBVH.MAX_DEPTH - 1) {
            s.tree.setLeaf(node, from, count);
            return;
        }
        // when all centroids coincide (no best axis), any even split is as good as another
        int mid = bestAxis < 0 ? from + count / 2
            : partition(s, from, to, bestAxis, cbox[bestAxis], cbox[bestAxis + 3] - cbox[bestAxis], bestBin);
        buildNode(s, from, mid, depth + 1);
        int right = s.tree.size();
        buildNode(s, mid, to, depth + 1);
        s.tree.setInterior(node, right);
    }

    private static int bin(double c, double lo, double extent) {
        int b = (int) (BINS * ((c - lo) / extent));
        return Math.max(0, Math.min(BINS - 1, b));
    }

    /** Moves primitives in bins 0..splitBin before the others; returns the first of the others. */
    private static int partition(State s, int from, int to, int axis, double lo, double extent, int splitBin) {
        int i = from;
        int j = to - 1;
        while (i <= j) {
            if (bin(s.centroids[3 * s.order[i] + axis], lo, extent) <= splitBin) {
                i++;
            } else {
                int t = s.order[i];
                s.order[i] = s.order[j];
                s.order[j] = t;
                j--;
            }
        }
        return i;
    }

    private static double[] unionBounds(State s, int from, int to) {
        double[] box = new double[6];
        resetBox(box, 0);
        for (int i = from; i < to; i++) {
            grow(box, 0, s.primBounds, 6 * s.order[i]);
        }
        return box;
    }

    private static double[] centroidBounds(State s, int from, int to) {
        double[] box = new double[6];
        resetBox(box, 0);
        for (int i = from; i < to; i++) {
            int c = 3 * s.order[i];
            for (int k = 0; k < 3; k++) {
                box[k] = Math.min(box[k], s.centroids[c + k]);
                box[k + 3] = Math.max(box[k + 3], s.centroids[c + k]);
            }
        }
        return box;
    }

    private static void resetBox(double[] b, int i) {
        b[i] = Double.POSITIVE_INFINITY;
        b[i + 1] = Double.POSITIVE_INFINITY;
        b[i + 2] = Double.POSITIVE_INFINITY;
        b[i + 3] = Double.NEGATIVE_INFINITY;
        b[i + 4] = Double.NEGATIVE_INFINITY;
        b[i + 5] = Double.NEGATIVE_INFINITY;
    }

    private static void grow(double[] b, int i, double[] other, int j) {
        for (int k = 0; k < 3; k++) {
            b[i + k] = Math.min(b[i + k], other[j + k]);
            b[i + 3 + k] = Math.max(b[i + 3 + k], other[j + 3 + k]);
        }
    }

    private static double surfaceArea(double[] b, int i) {
        double ex = b[i + 3] - b[i];
        double ey = b[i + 4] - b[i + 1];
        double ez = b[i + 5] - b[i + 2];
        if (!(ex >= 0 && ey >= 0 && ez >= 0)) {
            return 0;
        }
        return 2 * (ex * ey + ey * ez + ez * ex);
    }
}

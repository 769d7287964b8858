package raytracer.accel;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveAction;

/**
 * The report's BVH (section 6): split each node on the longest axis of its box, order its
 * primitives by centroid along that axis and halve them at the median; the children may overlap.
 * Instead of sorting at every level, a quickselect puts the median in place with the smaller
 * half before it, which is O(n) per level and O(n log n) in all.
 *
 * <p>Because a node always halves its count, the size of every subtree follows from its count
 * alone; each subtree therefore knows its place in the depth-first arrays before it is built, and
 * large subtrees are built in parallel with the same result as a serial build.
 */
public final class MedianSplitBuilder {
    /** Below this many primitives a subtree is built on the current thread. */
    private static final int PARALLEL_THRESHOLD = 32_768;

    private final int leafSize;

    public MedianSplitBuilder(int leafSize) {
        if (leafSize < 1) {
            throw new IllegalArgumentException("leaf size must be at least 1, got " + leafSize);
        }
        this.leafSize = leafSize;
    }

    /** Builds over primitives whose boxes are {@code primBounds[6i .. 6i+6)} = (x0, y0, z0, x1, y1, z1). */
    public FlatBVH build(double[] primBounds) {
        int n = primBounds.length / 6;
        if (n == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        double[] centroids = new double[3 * n];
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
            for (int k = 0; k < 3; k++) {
                centroids[3 * i + k] = 0.5 * (primBounds[6 * i + k] + primBounds[6 * i + 3 + k]);
            }
        }
        Map<Integer, Integer> sizes = new HashMap<>();
        int nodes = subtreeNodes(n, sizes);
        double[] bounds = new double[6 * nodes];
        int[] meta = new int[2 * nodes];
        Job root = new Job(primBounds, centroids, order, bounds, meta, sizes, 0, 0, n);
        if (n > PARALLEL_THRESHOLD) {
            ForkJoinPool.commonPool().invoke(root);
        } else {
            root.compute();
        }
        return new FlatBVH(bounds, meta, order, nodes);
    }

    /**
     * Nodes in a subtree over {@code count} primitives: one leaf, or a node and two halves. Only two
     * counts occur per level, so the memo stays tiny; it is filled before the parallel build and
     * only read during it.
     */
    private int subtreeNodes(int count, Map<Integer, Integer> memo) {
        if (count <= leafSize) {
            return 1;
        }
        Integer known = memo.get(count);
        if (known != null) {
            return known;
        }
        int half = count / 2;
        int nodes = 1 + subtreeNodes(half, memo) + subtreeNodes(count - half, memo);
        memo.put(count, nodes);
        return nodes;
    }

    /** Builds the subtree over order[from, to) into node index {@code node} and after. */
    private final class Job extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient double[] primBounds;
        private final transient double[] centroids;
        private final transient int[] order;
        private final transient double[] bounds;
        private final transient int[] meta;
        private final transient Map<Integer, Integer> sizes;
        private final int node;
        private final int from;
        private final int to;

        Job(double[] primBounds, double[] centroids, int[] order, double[] bounds, int[] meta,
            Map<Integer, Integer> sizes, int node, int from, int to) {
            this.primBounds = primBounds;
            this.centroids = centroids;
            this.order = order;
            this.bounds = bounds;
            this.meta = meta;
            this.sizes = sizes;
            this.node = node;
            this.from = from;
            this.to = to;
        }

        @Override
        protected void compute() {
            int count = to - from;
            unionBounds(node, from, to);
            if (count <= leafSize) {
                meta[2 * node] = from;
                meta[2 * node + 1] = count;
                return;
            }
            int axis = longestAxis(node);
            int mid = from + count / 2;
            Select.nth(order, centroids, axis, from, to, mid);
            int left = node + 1;
            int right = left + subtreeNodes(mid - from, sizes);
            meta[2 * node] = right;
            meta[2 * node + 1] = -(axis + 1);
            Job leftJob = new Job(primBounds, centroids, order, bounds, meta, sizes, left, from, mid);
            Job rightJob = new Job(primBounds, centroids, order, bounds, meta, sizes, right, mid, to);
            if (count > PARALLEL_THRESHOLD) {
                invokeAll(leftJob, rightJob);
            } else {
                leftJob.compute();
                rightJob.compute();
            }
        }

        private void unionBounds(int target, int lo, int hi) {
            double x0 = Double.POSITIVE_INFINITY;
            double y0 = Double.POSITIVE_INFINITY;
            double z0 = Double.POSITIVE_INFINITY;
            double x1 = Double.NEGATIVE_INFINITY;
            double y1 = Double.NEGATIVE_INFINITY;
            double z1 = Double.NEGATIVE_INFINITY;
            for (int i = lo; i < hi; i++) {
                int p = 6 * order[i];
                x0 = Math.min(x0, primBounds[p]);
                y0 = Math.min(y0, primBounds[p + 1]);
                z0 = Math.min(z0, primBounds[p + 2]);
                x1 = Math.max(x1, primBounds[p + 3]);
                y1 = Math.max(y1, primBounds[p + 4]);
                z1 = Math.max(z1, primBounds[p + 5]);
            }
            int b = 6 * target;
            bounds[b] = x0;
            bounds[b + 1] = y0;
            bounds[b + 2] = z0;
            bounds[b + 3] = x1;
            bounds[b + 4] = y1;
            bounds[b + 5] = z1;
        }

        private int longestAxis(int target) {
            int b = 6 * target;
            double ex = bounds[b + 3] - bounds[b];
            double ey = bounds[b + 4] - bounds[b + 1];
            double ez = bounds[b + 5] - bounds[b + 2];
            return ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
        }
    }
}

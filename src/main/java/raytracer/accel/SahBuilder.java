package raytracer.accel;

import java.util.Arrays;
import java.util.concurrent.RecursiveAction;

/**
 * A BVH built by the binned surface area heuristic (Wald, "On fast construction of SAH-based
 * bounding volume hierarchies", 2007; pbrt-v4 section 7.3.2): a node's primitives are binned by
 * centroid on each axis ({@link SahBins}) and split at the plane between bins of least expected
 * cost C = 1/2 + (N_L A_L + N_R A_R) / A, in units of one primitive test; a node of at most
 * {@code maxLeafSize} primitives that costs less as a leaf (C >= N) stays one.
 *
 * <p>Built as the median builder is: the primitives' boxes are outward-rounded floats that move
 * with their ids (and a mesh's vertex indices) through the partitions, so every pass reads one run
 * of memory; the children's boxes come from the bins and their centroid boxes from the partition,
 * so a node costs two passes over its primitives. A subtree over c primitives has at most c - 1
 * interior nodes, so it is given that many numbers before it is built: its left child's subtree
 * the c_L - 1 after it, its right child's the rest. Subtrees above a threshold are thus built in
 * parallel, on the caller's fork/join pool, into the same numbers as a serial build (numbers
 * left unused are never linked; the collapse into wide nodes packs the tree).
 */
public final class SahBuilder {
    /** Below this many primitives a subtree is built on the current thread. */
    private static final int PARALLEL_THRESHOLD = 32_768;
    /** The cost of visiting a node, in units of one primitive test (pbrt-v4's 1/2). */
    private static final double TRAVERSAL_COST = 0.5;
    /** Whether a node of at most the leaf size is split when the SAH says so (pbrt-v4), or is always a leaf. */
    private static final boolean SPLIT_SMALL_NODES = !Boolean.getBoolean("leafbysize");

    private final int maxLeafSize;
    private final int parallelThreshold;

    public SahBuilder(int maxLeafSize) {
        this(maxLeafSize, PARALLEL_THRESHOLD);
    }

    /** With subtrees of more than {@code parallelThreshold} primitives built as parallel tasks ({@code Integer.MAX_VALUE}: serially). */
    SahBuilder(int maxLeafSize, int parallelThreshold) {
        if (maxLeafSize < 1) {
            throw new IllegalArgumentException("leaf size must be at least 1, got " + maxLeafSize);
        }
        this.maxLeafSize = maxLeafSize;
        this.parallelThreshold = Math.max(parallelThreshold, 2);
    }

    /** Builds over primitives whose boxes are {@code primBounds[6i .. 6i+6)} = (x0, y0, z0, x1, y1, z1). */
    public FlatBVH build(double[] primBounds) {
        return build(FloatBoxes.roundOutward(primBounds), null);
    }

    /** Builds over the float boxes {@code boxes[6i .. 6i+6)}, rounded outward, which are reordered in place into the leaf order. */
    public FlatBVH build(float[] boxes) {
        return build(boxes, null);
    }

    /**
     * As {@link #build(float[])}, and {@code carried}, three ints per primitive (a mesh's vertex
     * indices), travels with the boxes into the leaf order, as in {@link MedianSplitBuilder#build(float[], int[])}.
     */
    public FlatBVH build(float[] boxes, int[] carried) {
        return binary(boxes, carried).flat();
    }

    /** The binary tree that {@link #build(float[], int[])} collapses into wide nodes. */
    BinaryTree binary(float[] boxes, int[] carried) {
        int n = boxes.length / 6;
        if (n == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        if (carried != null && carried.length != 3 * n) {
            throw new IllegalArgumentException("need three carried ints per primitive, got " + carried.length + " for " + n);
        }
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = i;
        }
        float[] root = new float[12];
        FloatBoxes.union(boxes, 0, n, root, 0);
        FloatBoxes.centroidBox(boxes, 0, n, root, 6);
        Build build = new Build(boxes, ids, carried, new BvhNodes(n - 1), root);
        Task task = new Task(build, -1, 0, 0, 0, n, 1, root, 6);
        if (n > parallelThreshold) {
            task.invoke(); // its subtrees fork into the caller's pool (the run's one pool), else the common pool
        } else {
            task.compute();
        }
        float[] rootBox = Arrays.copyOf(root, 6);
        return build.rootIsLeaf ? new BinaryTree(new BvhNodes(0), ids, rootBox, 0, n) : new BinaryTree(build.nodes, ids, rootBox, 0, 0);
    }

    /** One build's arrays: the primitives' boxes, ids and carried ints, which move together, and the nodes made. */
    private static final class Build {
        final float[] boxes;
        final int[] ids;
        final int[] carried;
        final BvhNodes nodes;
        /** The root's box and its centroids' box. */
        final float[] root;
        /** Set by the root's task, read after it is joined. */
        boolean rootIsLeaf;

        Build(float[] boxes, int[] ids, int[] carried, BvhNodes nodes, float[] root) {
            this.boxes = boxes;
            this.ids = ids;
            this.carried = carried;
            this.nodes = nodes;
            this.root = root;
        }
    }

    /** One task's scratch: its bins, and per depth the centroid boxes of the two children made there. */
    private static final class Scratch {
        final SahBins bins = new SahBins();
        final float[] centroids = new float[12 * (FlatBVH.MAX_DEPTH + 1)];
    }

    /**
     * Builds the subtree over positions from .. to - 1 as the child on {@code side} of
     * {@code parent} (-1: the root), whose box that node already holds, numbering its interior
     * nodes from {@code node}; its centroids' box is {@code centroids[at .. at + 6)}.
     */
    private void subtree(Build b, Scratch s, int parent, int side, int node, int from, int to, int depth,
                         float[] centroids, int at) {
        int count = to - from;
        float[] box = parent < 0 ? b.root : b.nodes.bounds;
        int boxAt = parent < 0 ? 0 : BvhNodes.boxAt(parent, side);
        SahBins bins = s.bins;
        boolean split = false;
        boolean planeFound = false;
        if (count > (SPLIT_SMALL_NODES ? 1 : maxLeafSize) && depth < FlatBVH.MAX_DEPTH - 1) {
            planeFound = bins.fill(b.boxes, from, to, centroids, at) && bins.sweep();
            split = count > maxLeafSize
                    || planeFound && TRAVERSAL_COST + bins.bestCost / SahBins.halfArea(box, boxAt) < count;
        }
        if (!split) {
            if (parent < 0) {
                b.rootIsLeaf = true;
            } else {
                b.nodes.setLeaf(parent, side, from, count);
            }
            return;
        }
        if (parent >= 0) {
            b.nodes.setInterior(parent, side, node);
        }
        float[] children = s.centroids;
        int childrenAt = 12 * depth;
        int mid;
        if (planeFound) {
            mid = partition(b, from, to, bins, children, childrenAt);
            bins.union(0, bins.bestBin + 1, b.nodes.bounds, BvhNodes.boxAt(node, BvhNodes.LEFT));
            bins.union(bins.bestBin + 1, bins.lastBin() + 1, b.nodes.bounds, BvhNodes.boxAt(node, BvhNodes.RIGHT));
        } else {
            // the centroids do not spread, or all fell in one bin: halve at the median on the box's longest axis
            mid = from + count / 2;
            BoxSelect.nth(b.boxes, b.ids, b.carried, FloatBoxes.longestAxis(box, boxAt), from, to, mid);
            FloatBoxes.union(b.boxes, from, mid, b.nodes.bounds, BvhNodes.boxAt(node, BvhNodes.LEFT));
            FloatBoxes.union(b.boxes, mid, to, b.nodes.bounds, BvhNodes.boxAt(node, BvhNodes.RIGHT));
            FloatBoxes.centroidBox(b.boxes, from, mid, children, childrenAt);
            FloatBoxes.centroidBox(b.boxes, mid, to, children, childrenAt + 6);
        }
        int right = node + (mid - from);
        if (count > parallelThreshold) {
            Task.invokeAll(new Task(b, node, BvhNodes.LEFT, node + 1, from, mid, depth + 1, children, childrenAt),
                           new Task(b, node, BvhNodes.RIGHT, right, mid, to, depth + 1, children, childrenAt + 6));
        } else {
            subtree(b, s, node, BvhNodes.LEFT, node + 1, from, mid, depth + 1, children, childrenAt);
            subtree(b, s, node, BvhNodes.RIGHT, right, mid, to, depth + 1, children, childrenAt + 6);
        }
    }

    /**
     * Moves the primitives of bins up to the best one on the best axis before the others, and
     * writes the centroid boxes of the two parts to {@code out[at .. at + 12)}; returns the first
     * position of the second part. One pass: each primitive's centroid joins its part's box when
     * its place is settled.
     */
    private static int partition(Build b, int from, int to, SahBins bins, float[] out, int at) {
        float[] p = b.boxes;
        int axis = bins.axis();
        int last = bins.bestBin;
        float lo = bins.low();
        float scale = bins.scale();
        int lastBin = bins.lastBin();
        float[] left = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                        Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        float[] right = left.clone();
        int i = from;
        int j = to - 1;
        for (;;) {
            while (i <= j && SahBins.bin(FloatBoxes.centroidKey(p, i, axis), lo, scale, lastBin) <= last) {
                FloatBoxes.growCentroidBox(p, i, left);
                i++;
            }
            while (i <= j && SahBins.bin(FloatBoxes.centroidKey(p, j, axis), lo, scale, lastBin) > last) {
                FloatBoxes.growCentroidBox(p, j, right);
                j--;
            }
            if (i >= j) {
                break;
            }
            BoxSelect.swap(p, b.ids, b.carried, i, j);
            FloatBoxes.growCentroidBox(p, i, left);
            FloatBoxes.growCentroidBox(p, j, right);
            i++;
            j--;
        }
        System.arraycopy(left, 0, out, at, 6);
        System.arraycopy(right, 0, out, at + 6, 6);
        return i;
    }

    /** A subtree as a fork/join task, with its own scratch and a copy of its centroids' box. */
    private final class Task extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient Build build;
        private final int parent;
        private final int side;
        private final int node;
        private final int from;
        private final int to;
        private final int depth;
        private final float[] centroids = new float[6];

        Task(Build build, int parent, int side, int node, int from, int to, int depth, float[] centroids, int at) {
            this.build = build;
            this.parent = parent;
            this.side = side;
            this.node = node;
            this.from = from;
            this.to = to;
            this.depth = depth;
            System.arraycopy(centroids, at, this.centroids, 0, 6);
        }

        @Override
        protected void compute() {
            subtree(build, new Scratch(), parent, side, node, from, to, depth, centroids, 0);
        }
    }
}

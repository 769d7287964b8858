package raytracer.accel;

import java.util.concurrent.RecursiveAction;

/**
 * A BVH built by the binned surface area heuristic (Wald, "On fast construction of SAH-based
 * bounding volume hierarchies", 2007; pbrt-v4 section 7.3.2): a node's primitives are binned by
 * centroid along the longest axis of the node's box ({@link SahBins}) and split at the
 * plane between bins where N_L A_L + N_R A_R is least, A the surface area of a side's box. A node
 * of at most {@code maxLeafSize} primitives is a leaf. pbrt-v4 splits such a node further when
 * the heuristic expects that to pay (a node visit costing half a primitive test); here that made
 * leaves of 1.3 triangles on average, twice the nodes, and the dragon's rays 10% slower
 * (tools/studies/bvh/README.md): a visit of a binary node costs this traversal more than that.
 *
 * <p>Built as the median builder is: the primitives' boxes are outward-rounded floats that move
 * with their ids (and a mesh's vertex indices) through the partitions, so every pass reads one run
 * of memory; the children's boxes come from the bins, and the partition bins each primitive for
 * the child it goes to, so a level of the tree costs one pass over its primitives. A subtree over c primitives has at most c - 1
 * interior nodes, so it is given that many numbers before it is built: its left child's subtree
 * the c_L - 1 after its own, its right child's the rest. Subtrees above a threshold are thus
 * built in parallel, on the caller's fork/join pool, into the same numbers as a serial build;
 * {@link BinaryTree#flat} then packs the numbers that were used.
 */
public final class SahBuilder {
    /** Below this many primitives a subtree is built on the current thread. */
    private static final int PARALLEL_THRESHOLD = 32_768;

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

    /** The tree that {@link #build(float[], int[])} packs, its nodes numbered with gaps. */
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
        float[] root = new float[6];
        FloatBoxes.union(boxes, 0, n, root, 0);
        Build build = new Build(boxes, ids, carried, new BvhNodes(n - 1), root);
        Task task = new Task(build, -1, 0, 0, 0, n, 1, null);
        if (n > parallelThreshold) {
            task.invoke(); // its subtrees fork into the caller's pool (the run's one pool), else the common pool
        } else {
            task.compute();
        }
        return n <= maxLeafSize ? new BinaryTree(new BvhNodes(0), ids, root, 0, n) : new BinaryTree(build.nodes(), ids, root, 0, 0);
    }

    /** One build's arrays: the primitives' boxes, ids and carried ints, which move together, the nodes made, and the root's box. */
    private record Build(float[] boxes, int[] ids, int[] carried, BvhNodes nodes, float[] root) {
    }

    /** One task's scratch: per depth, the bins of the two children made there. */
    private static final class Scratch {
        final SahBins[] bins = new SahBins[2 * (FlatBVH.MAX_DEPTH + 1)];

        SahBins bins(int depth, int side) {
            int k = 2 * depth + side;
            if (bins[k] == null) {
                bins[k] = new SahBins();
            }
            return bins[k];
        }
    }

    /**
     * Builds the subtree over positions from .. to - 1 as the child on {@code side} of
     * {@code parent} (-1: the root), whose box that node already holds, numbering its interior
     * nodes from {@code node}; {@code filled} holds its primitives binned, or is null.
     */
    private void subtree(Build b, Scratch s, int parent, int side, int node, int from, int to, int depth, SahBins filled) {
        int count = to - from;
        if (count <= maxLeafSize || depth >= FlatBVH.MAX_DEPTH - 1) {
            if (parent >= 0) {
                b.nodes().setLeaf(parent, side, from, count);
            }
            return;
        }
        if (parent >= 0) {
            b.nodes().setInterior(parent, side, node);
        }
        BvhNodes nodes = b.nodes();
        float[] box = parent < 0 ? b.root() : nodes.bounds;
        int boxAt = parent < 0 ? 0 : BvhNodes.boxAt(parent, side);
        SahBins bins = filled;
        if (bins == null) {
            bins = s.bins(depth, side);
            if (bins.prepare(box, boxAt, count)) {
                bins.fill(b.boxes(), from, to);
            } else {
                bins = null;
            }
        }
        int leftAt = BvhNodes.boxAt(node, BvhNodes.LEFT);
        int rightAt = BvhNodes.boxAt(node, BvhNodes.RIGHT);
        int mid;
        SahBins left = null;
        SahBins right = null;
        if (bins != null && bins.sweep()) {
            bins.union(0, bins.bestBin + 1, nodes.bounds, leftAt);
            bins.union(bins.bestBin + 1, bins.lastBin() + 1, nodes.bounds, rightAt);
            // the children's bins, filled as the partition places their primitives
            left = childBins(s, depth + 1, BvhNodes.LEFT, nodes.bounds, leftAt, bins.leftCount);
            right = childBins(s, depth + 1, BvhNodes.RIGHT, nodes.bounds, rightAt, count - bins.leftCount);
            mid = bins.partition(b.boxes(), b.ids(), b.carried(), from, to, left, right);
        } else {
            // the box is flat along its longest axis, or every centroid fell in one bin: halve at the median
            mid = from + count / 2;
            BoxSelect.nth(b.boxes(), b.ids(), b.carried(), FloatBoxes.longestAxis(box, boxAt), from, to, mid);
            FloatBoxes.union(b.boxes(), from, mid, nodes.bounds, leftAt);
            FloatBoxes.union(b.boxes(), mid, to, nodes.bounds, rightAt);
        }
        int rightNode = node + (mid - from);
        if (count > parallelThreshold) {
            // each task takes one of the children's bins from this thread's scratch, which this
            // thread leaves alone until both are done
            Task.invokeAll(new Task(b, node, BvhNodes.LEFT, node + 1, from, mid, depth + 1, left),
                           new Task(b, node, BvhNodes.RIGHT, rightNode, mid, to, depth + 1, right));
        } else {
            subtree(b, s, node, BvhNodes.LEFT, node + 1, from, mid, depth + 1, left);
            subtree(b, s, node, BvhNodes.RIGHT, rightNode, mid, to, depth + 1, right);
        }
    }

    /** Bins prepared for a child of {@code count} primitives in the box {@code box[at .. at + 6)}, or null when it will be a leaf or its box is flat. */
    private SahBins childBins(Scratch s, int depth, int side, float[] box, int at, int count) {
        if (count <= maxLeafSize || depth >= FlatBVH.MAX_DEPTH - 1) {
            return null;
        }
        SahBins bins = s.bins(depth, side);
        return bins.prepare(box, at, count) ? bins : null;
    }

    /** A subtree as a fork/join task, with its own scratch and its root's bins, or null. */
    private final class Task extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient Build build;
        private final int parent;
        private final int side;
        private final int node;
        private final int from;
        private final int to;
        private final int depth;
        private final transient SahBins filled;

        Task(Build build, int parent, int side, int node, int from, int to, int depth, SahBins filled) {
            this.build = build;
            this.parent = parent;
            this.side = side;
            this.node = node;
            this.from = from;
            this.to = to;
            this.depth = depth;
            this.filled = filled;
        }

        @Override
        protected void compute() {
            subtree(build, new Scratch(), parent, side, node, from, to, depth, filled);
        }
    }
}

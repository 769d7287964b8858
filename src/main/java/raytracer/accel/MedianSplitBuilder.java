package raytracer.accel;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.RecursiveAction;

/**
 * The report's median-split BVH (section 6), built fast: it makes the same tree as
 * {@link SortedMedianBuilder}, the algorithm as the report states it (SortedMedianBuilderTest
 * checks node for node), but instead of sorting each node's primitives it selects the median in
 * place ({@link BoxSelect}): O(n) per level, O(n log n) in all.
 *
 * <p>The primitives' boxes are floats rounded outward and travel with their ids through the
 * selections, so every pass over a node's primitives reads one contiguous run of memory (an index
 * array into boxes in file order made each pass a random walk). The children's boxes are found by
 * one pass at their parent and written straight into its node.
 *
 * <p>Because a node always halves its count, the size of every subtree follows from its count
 * alone; each subtree therefore knows its place in the depth-first node order before it is built,
 * and large subtrees are built in parallel into the same nodes as a serial build
 * (MedianSplitBuilderTest).
 */
public final class MedianSplitBuilder {
    /** Below this many primitives a subtree is built on the current thread. */
    private static final int PARALLEL_THRESHOLD = 32_768;

    private final int leafSize;
    private final int parallelThreshold;

    public MedianSplitBuilder(int leafSize) {
        this(leafSize, PARALLEL_THRESHOLD);
    }

    /**
     * With subtrees of more than {@code parallelThreshold} primitives built as parallel tasks (for
     * tests: {@code Integer.MAX_VALUE} builds serially). Kept above twice the leaf size, so that
     * both halves of a parallel node are interior nodes.
     */
    MedianSplitBuilder(int leafSize, int parallelThreshold) {
        if (leafSize < 1) {
            throw new IllegalArgumentException("leaf size must be at least 1, got " + leafSize);
        }
        this.leafSize = leafSize;
        this.parallelThreshold = Math.max(parallelThreshold, 2 * leafSize + 1);
    }

    /** Builds over primitives whose boxes are {@code primBounds[6i .. 6i+6)} = (x0, y0, z0, x1, y1, z1). */
    public FlatBVH build(double[] primBounds) {
        return build(FloatBoxes.roundOutward(primBounds));
    }

    /**
     * Builds over primitives whose boxes are the floats {@code boxes[6i .. 6i+6)}, already rounded
     * outward. The array is reordered in place into the leaf order.
     */
    public FlatBVH build(float[] boxes) {
        return build(boxes, null);
    }

    /**
     * As {@link #build(float[])}, and {@code carried}, three ints per primitive (a mesh's vertex
     * indices), travels with the boxes: it comes out in the leaf order, as {@code carried[3 order[k] ..]}
     * was, with no copy of it (a permutation applied afterwards in place would follow its cycles,
     * one dependent random read a step, some ten times as slow as a copy).
     */
    public FlatBVH build(float[] boxes, int[] carried) {
        return binary(boxes, carried).flat();
    }

    /** The binary tree that {@link #build(float[], int[])} flattens: the same nodes, numbered depth-first. */
    BinaryTree binary(float[] boxes, int[] carried) {
        int n = boxes.length / 6;
        if (n == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        if (carried != null && carried.length != 3 * n) {
            throw new IllegalArgumentException("need three carried ints per primitive, got " + carried.length + " for " + n);
        }
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        float[] rootBox = new float[6];
        FloatBoxes.union(boxes, 0, n, rootBox, 0);
        if (n <= leafSize) {
            return new BinaryTree(new BvhNodes(0), order, rootBox, 0, n);
        }
        Map<Integer, Integer> sizes = new HashMap<>();
        Build build = new Build(boxes, order, carried, new BvhNodes(interiorNodes(n, sizes)), sizes);
        Job job = new Job(build, 0, 0, n, FloatBoxes.longestAxis(rootBox, 0));
        if (n > parallelThreshold) {
            job.invoke(); // its subtrees fork into the caller's pool (the run's one pool), else the common pool
        } else {
            job.compute();
        }
        return new BinaryTree(build.nodes, order, rootBox, 0, 0);
    }

    /**
     * Interior nodes in a subtree over {@code count} primitives. Only two counts occur per level,
     * so the memo stays tiny; it is filled before the parallel build and only read during it.
     */
    private int interiorNodes(int count, Map<Integer, Integer> memo) {
        if (count <= leafSize) {
            return 0;
        }
        Integer known = memo.get(count);
        if (known != null) {
            return known;
        }
        int half = count / 2;
        int nodes = 1 + interiorNodes(half, memo) + interiorNodes(count - half, memo);
        memo.put(count, nodes);
        return nodes;
    }

    /** One build's arrays: the primitives' boxes, ids and carried ints, which move together, and the nodes made. */
    private record Build(float[] boxes, int[] order, int[] carried, BvhNodes nodes, Map<Integer, Integer> sizes) {
    }

    /**
     * Halves positions from .. to - 1 at their median on {@code axis} and writes both children's
     * boxes into {@code node}, where the children pick their axes from (nothing is allocated per node).
     */
    private static void halve(Build b, int node, int from, int to, int axis) {
        int mid = from + (to - from) / 2;
        BoxSelect.nth(b.boxes(), b.order(), b.carried(), axis, from, to, mid);
        FloatBoxes.union(b.boxes(), from, mid, b.nodes().bounds, BvhNodes.boxAt(node, BvhNodes.LEFT));
        FloatBoxes.union(b.boxes(), mid, to, b.nodes().bounds, BvhNodes.boxAt(node, BvhNodes.RIGHT));
    }

    /** The longest axis of the box of {@code node}'s child on {@code side}. */
    private static int axisOf(BvhNodes nodes, int node, int side) {
        return FloatBoxes.longestAxis(nodes.bounds, BvhNodes.boxAt(node, side));
    }

    /**
     * Builds the subtree over positions from .. to - 1, more than a leaf, depth-first into
     * {@code node} and the nodes after it; returns the first node after the subtree. The right
     * child's number is known once the left subtree is done, so no size table is needed.
     */
    private int buildSerial(Build b, int node, int from, int to, int axis) {
        halve(b, node, from, to, axis);
        int mid = from + (to - from) / 2;
        int next = node + 1;
        next = child(b, node, BvhNodes.LEFT, next, from, mid, axis);
        return child(b, node, BvhNodes.RIGHT, next, mid, to, axis);
    }

    /**
     * Makes positions from .. to - 1 the child of {@code node} on {@code side}: a leaf, its
     * primitives in order along the parent's axis as a sort would leave them, or a subtree built
     * from node {@code next} on. Returns the first node after it.
     */
    private int child(Build b, int node, int side, int next, int from, int to, int parentAxis) {
        if (to - from <= leafSize) {
            BoxSelect.sort(b.boxes(), b.order(), b.carried(), parentAxis, from, to);
            b.nodes().setLeaf(node, side, from, to - from);
            return next;
        }
        b.nodes().setInterior(node, side, next);
        return buildSerial(b, next, from, to, axisOf(b.nodes(), node, side));
    }

    /**
     * Builds the subtree over positions from .. to - 1 into node {@code node} and after: above
     * the parallel threshold both halves become parallel tasks, whose node numbers come from
     * {@link #interiorNodes}; below it, {@link #buildSerial}.
     */
    private final class Job extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient Build build;
        private final int node;
        private final int from;
        private final int to;
        private final int axis;

        Job(Build build, int node, int from, int to, int axis) {
            this.build = build;
            this.node = node;
            this.from = from;
            this.to = to;
            this.axis = axis;
        }

        @Override
        protected void compute() {
            if (to - from <= parallelThreshold) {
                buildSerial(build, node, from, to, axis);
                return;
            }
            halve(build, node, from, to, axis);
            int mid = from + (to - from) / 2;
            // both halves are interior nodes here: the threshold is above twice the leaf size
            int left = node + 1;
            int right = left + interiorNodes(mid - from, build.sizes());
            BvhNodes nodes = build.nodes();
            nodes.setInterior(node, BvhNodes.LEFT, left);
            nodes.setInterior(node, BvhNodes.RIGHT, right);
            invokeAll(new Job(build, left, from, mid, axisOf(nodes, node, BvhNodes.LEFT)),
                      new Job(build, right, mid, to, axisOf(nodes, node, BvhNodes.RIGHT)));
        }
    }
}

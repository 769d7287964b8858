package raytracer.accel;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.RecursiveAction;

/**
 * The report's BVH (section 6): split each node on the longest axis of its box, order its
 * primitives by centroid along that axis and halve them at the median; the children may overlap.
 * Instead of sorting at every level, a quickselect ({@link BoxSelect}) puts the median in place with
 * the smaller half before it: O(n) per level, O(n log n) in all.
 *
 * <p>The primitives' boxes are floats rounded outward and travel with their primitive through the
 * selections, so every pass over a node's primitives reads one contiguous run of memory (an index
 * array into boxes in file order made each pass a random walk). The children's boxes are found by
 * one pass at their parent and written straight into its traversal record.
 *
 * <p>Because a node always halves its count, the size of every subtree follows from its count
 * alone; each subtree therefore knows its place in the depth-first records before it is built, and
 * large subtrees are built in parallel with the same records and leaf order as a serial build
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
        float[] boxes = new float[primBounds.length];
        for (int i = 0; i < primBounds.length; i += 6) {
            for (int k = 0; k < 3; k++) {
                boxes[i + k] = FlatBVH.roundDown(primBounds[i + k]);
                boxes[i + 3 + k] = FlatBVH.roundUp(primBounds[i + 3 + k]);
            }
        }
        return build(boxes);
    }

    /**
     * Builds over primitives whose boxes are the floats {@code boxes[6i .. 6i+6)}, already rounded
     * outward. The array is reordered in place into the leaf order.
     */
    public FlatBVH build(float[] boxes) {
        int n = boxes.length / 6;
        if (n == 0) {
            throw new IllegalArgumentException("a BVH needs at least one primitive");
        }
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        float[] root = new float[6];
        BoxSelect.union(boxes, 0, n, root, 0);
        int[] rootBox = new int[6];
        for (int k = 0; k < 6; k++) {
            rootBox[k] = Float.floatToRawIntBits(root[k]);
        }
        Map<Integer, Integer> sizes = new HashMap<>();
        int interior = interiorNodes(n, sizes);
        if (n <= leafSize) {
            return new FlatBVH(new int[0], order, rootBox, 0, n, 1);
        }
        int[] records = new int[FlatBVH.RECORD * interior];
        Job job = new Job(boxes, order, records, sizes, 0, 0, n, longestAxis(root, 0));
        if (n > parallelThreshold) {
            job.invoke(); // its subtrees fork into the caller's pool (the run's one pool), else the common pool
        } else {
            job.compute();
        }
        return new FlatBVH(records, order, rootBox, 0, 0, 2 * interior + 1);
    }

    /**
     * Interior nodes in a subtree over {@code count} primitives (a binary tree has one leaf more).
     * Only two counts occur per level, so the memo stays tiny; it is filled before the parallel
     * build and only read during it.
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

    private static int longestAxis(float[] box, int at) {
        float ex = box[at + 3] - box[at];
        float ey = box[at + 4] - box[at + 1];
        float ez = box[at + 5] - box[at + 2];
        return ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
    }

    /**
     * Halves positions [from, to) at their median on {@code axis} and writes both children's boxes
     * into {@code record}; returns the boxes (left, then right) so the children can pick their axes.
     */
    private static float[] halve(float[] boxes, int[] order, int[] records, int record, int from, int to, int axis) {
        int mid = from + (to - from) / 2;
        BoxSelect.nth(boxes, order, axis, from, to, mid);
        float[] childBoxes = new float[12];
        BoxSelect.union(boxes, from, mid, childBoxes, 0);
        BoxSelect.union(boxes, mid, to, childBoxes, 6);
        int r = FlatBVH.RECORD * record;
        for (int k = 0; k < 12; k++) {
            records[r + k] = Float.floatToRawIntBits(childBoxes[k]);
        }
        return childBoxes;
    }

    /**
     * Builds the subtree over positions [from, to), more than a leaf, depth-first into
     * {@code record} and the records after it; returns the first record after the subtree. The
     * right child's record is known once the left subtree is done, so no size table is needed.
     */
    private int buildSerial(float[] boxes, int[] order, int[] records, int record, int from, int to, int axis) {
        float[] childBoxes = halve(boxes, order, records, record, from, to, axis);
        int mid = from + (to - from) / 2;
        int r = FlatBVH.RECORD * record;
        int next = record + 1;
        if (mid - from <= leafSize) {
            records[r + FlatBVH.LINK] = from;
            records[r + FlatBVH.COUNT] = mid - from;
        } else {
            records[r + FlatBVH.LINK] = next;
            next = buildSerial(boxes, order, records, next, from, mid, longestAxis(childBoxes, 0));
        }
        if (to - mid <= leafSize) {
            records[r + FlatBVH.LINK + 1] = mid;
            records[r + FlatBVH.COUNT + 1] = to - mid;
        } else {
            records[r + FlatBVH.LINK + 1] = next;
            next = buildSerial(boxes, order, records, next, mid, to, longestAxis(childBoxes, 6));
        }
        return next;
    }

    /**
     * Builds the subtree over positions [from, to) into record {@code record} and after: above
     * the parallel threshold both halves become parallel tasks, whose record
     * numbers come from {@link #interiorNodes}; below it, {@link #buildSerial}.
     */
    private final class Job extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient float[] boxes;
        private final transient int[] order;
        private final transient int[] records;
        private final transient Map<Integer, Integer> sizes;
        private final int record;
        private final int from;
        private final int to;
        private final int axis;

        Job(float[] boxes, int[] order, int[] records, Map<Integer, Integer> sizes, int record, int from, int to,
            int axis) {
            this.boxes = boxes;
            this.order = order;
            this.records = records;
            this.sizes = sizes;
            this.record = record;
            this.from = from;
            this.to = to;
            this.axis = axis;
        }

        @Override
        protected void compute() {
            if (to - from <= parallelThreshold) {
                buildSerial(boxes, order, records, record, from, to, axis);
                return;
            }
            float[] childBoxes = halve(boxes, order, records, record, from, to, axis);
            int mid = from + (to - from) / 2;
            // both halves are interior nodes here: the threshold is above twice the leaf size
            int leftRecord = record + 1;
            int rightRecord = leftRecord + interiorNodes(mid - from, sizes);
            int r = FlatBVH.RECORD * record;
            records[r + FlatBVH.LINK] = leftRecord;
            records[r + FlatBVH.LINK + 1] = rightRecord;
            invokeAll(new Job(boxes, order, records, sizes, leftRecord, from, mid, longestAxis(childBoxes, 0)),
                      new Job(boxes, order, records, sizes, rightRecord, mid, to, longestAxis(childBoxes, 6)));
        }
    }
}

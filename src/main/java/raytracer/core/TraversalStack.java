package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.SlabRay;

/**
 * One worker's scratch for BVH traversals (a field of its {@link WorkerScratch}): for each
 * traversal in progress, a {@link Frame} with the subtrees it has still to visit and its ray's
 * slab-test constants. Traversals nest (a mesh's BVH searched from a leaf of the scene's BVH,
 * possibly through instances), so a traversal takes the next frame with {@link #push} and gives it
 * back with {@link #pop}; the frame below stays as its traversal left it.
 */
public final class TraversalStack {
    /** The deepest tree the builders produce. */
    public static final int MAX_DEPTH = 64;
    /** Children of a node of the wide trees searched, and so of the entries one node's test yields. */
    public static final int WIDTH = 4;
    /** Subtrees a traversal may have stacked: all but one child per level, and the start. */
    public static final int STACK_SIZE = (WIDTH - 1) * MAX_DEPTH + 1;
    /** BVHs searched one inside another at most this deep. */
    public static final int MAX_NESTING = 8;

    /**
     * One traversal's stack: entry i is a subtree (its link and primitive count, as the tree
     * stores a child) and the distance at which the ray enters its box; and where one node's
     * test puts what it found of its children.
     */
    public static final class Frame {
        public final int[] links = new int[STACK_SIZE];
        public final int[] counts = new int[STACK_SIZE];
        public final double[] entries = new double[STACK_SIZE];
        public final long[] keys = new long[WIDTH];
        public final SlabRay ray = new SlabRay();
    }

    private final Frame[] frames = new Frame[MAX_NESTING];
    private int nesting;

    public TraversalStack() {
        for (int i = 0; i < MAX_NESTING; i++) {
            frames[i] = new Frame();
        }
    }

    /** Starts a traversal of {@code ray}: its frame, with the ray's slab constants loaded. */
    public Frame push(Ray ray) {
        if (nesting == MAX_NESTING) {
            throw new IllegalStateException("BVHs nested deeper than " + MAX_NESTING);
        }
        Frame frame = frames[nesting++];
        frame.ray.load(ray);
        return frame;
    }

    /** Ends the traversal that took the top frame. */
    public void pop() {
        nesting--;
    }
}

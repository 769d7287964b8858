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
    /** The deepest tree the builders produce: a traversal stacks at most one subtree per level. */
    public static final int MAX_DEPTH = 64;
    /** BVHs searched one inside another at most this deep. */
    public static final int MAX_NESTING = 8;

    /**
     * One traversal's stack: entry i is a subtree (its link and primitive count, as the tree
     * stores a child) and the distance at which the ray enters its box.
     */
    public static final class Frame {
        public final int[] links = new int[MAX_DEPTH];
        public final int[] counts = new int[MAX_DEPTH];
        public final double[] entries = new double[MAX_DEPTH];
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

package raytracer.accel;

import java.util.Arrays;

/**
 * A BVH as a recursive builder grows it, one node at a time in depth-first order, so that a node's
 * left child is the node after it: each node has its box (doubles) and, once its subtree is built,
 * either its right child or its run of primitives in the leaf order. {@link #flatten} packs it
 * into a {@link FlatBVH}.
 */
final class DepthFirstTree {
    private double[] boxes = new double[6 * 16];
    /** Per node: the right child (interior node) or the first primitive in the leaf order (leaf). */
    private int[] links = new int[16];
    /** Per node: its primitive count if it is a leaf, 0 if it is an interior node. */
    private int[] counts = new int[16];
    private int size;

    /** Appends a node with the box {@code box[at .. at + 6)}; returns its number. */
    int add(double[] box, int at) {
        if (size == links.length) {
            links = Arrays.copyOf(links, 2 * size);
            counts = Arrays.copyOf(counts, 2 * size);
            boxes = Arrays.copyOf(boxes, 12 * size);
        }
        System.arraycopy(box, at, boxes, 6 * size, 6);
        return size++;
    }

    /** The number the next node will get: a node's right child, once its left subtree is complete. */
    int size() {
        return size;
    }

    void setLeaf(int node, int first, int count) {
        links[node] = first;
        counts[node] = count;
    }

    void setInterior(int node, int rightChild) {
        links[node] = rightChild;
        counts[node] = 0;
    }

    /**
     * The tree in the layout of {@link BvhNodes}, its leaves listing their primitives in
     * {@code order}; boxes are rounded outward to floats.
     */
    BinaryTree flatten(int[] order) {
        // the interior nodes, numbered in the same depth-first order
        int[] interiorNumber = new int[size];
        int interior = 0;
        for (int node = 0; node < size; node++) {
            interiorNumber[node] = counts[node] > 0 ? -1 : interior++;
        }
        float[] floats = FloatBoxes.roundOutward(Arrays.copyOf(boxes, 6 * size));
        BvhNodes nodes = new BvhNodes(interior);
        for (int node = 0; node < size; node++) {
            if (counts[node] > 0) {
                continue;
            }
            int[] sides = {node + 1, links[node]};
            for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
                int child = sides[side];
                nodes.setBox(interiorNumber[node], side, floats, 6 * child);
                if (counts[child] > 0) {
                    nodes.setLeaf(interiorNumber[node], side, links[child], counts[child]);
                } else {
                    nodes.setInterior(interiorNumber[node], side, interiorNumber[child]);
                }
            }
        }
        float[] rootBox = Arrays.copyOf(floats, 6);
        boolean rootIsLeaf = counts[0] > 0;
        return new BinaryTree(nodes, order, rootBox, rootIsLeaf ? links[0] : 0, rootIsLeaf ? counts[0] : 0);
    }
}

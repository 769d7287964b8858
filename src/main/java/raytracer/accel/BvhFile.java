package raytracer.accel;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * A {@link FlatBVH} in bytes, for the mesh cache: the arrays of {@link BvhNodes}, the leaf order and
 * the root, each copied in bulk (little-endian, the order of the machines this runs on, so the
 * copies are plain memory copies).
 *
 * <pre>
 *   int nodes, int primitives
 *   float[12 nodes] bounds, int[4 nodes] children, int[primitives] order
 *   float[6] root box, int root link, int root count
 * </pre>
 *
 * <p><b>Whoever changes the layout of {@link BvhNodes} or {@link FlatBVH} (what an array holds,
 * their order, a new field) must change it here and add 1 to {@link #VERSION}</b>: a cache written
 * by another version is then rebuilt rather than misread.
 */
public final class BvhFile {
    /** The layout above; the mesh cache keys its files by it. */
    public static final int VERSION = 1;

    private BvhFile() {
    }

    /** The bytes {@link #write} takes for {@code bvh}. */
    public static long size(FlatBVH bvh) {
        return 4L * (2 + bvh.nodes.bounds.length + bvh.nodes.children.length + bvh.order.length + 6 + 2);
    }

    /** Writes {@code bvh} at {@code out}'s position, which it advances; {@code out} is little-endian. */
    public static void write(FlatBVH bvh, ByteBuffer out) {
        requireLittleEndian(out);
        out.putInt(bvh.nodes.count()).putInt(bvh.order.length);
        out.asFloatBuffer().put(bvh.nodes.bounds);
        out.position(out.position() + 4 * bvh.nodes.bounds.length);
        out.asIntBuffer().put(bvh.nodes.children);
        out.position(out.position() + 4 * bvh.nodes.children.length);
        out.asIntBuffer().put(bvh.order);
        out.position(out.position() + 4 * bvh.order.length);
        for (float f : bvh.rootBox) {
            out.putFloat(f);
        }
        out.putInt(bvh.rootLink).putInt(bvh.rootCount);
    }

    /**
     * Reads a tree written by {@link #write} from {@code in}'s position, which it advances. Links
     * and counts are checked against the arrays, so that no traversal can leave them; a tree that
     * fails is an IllegalArgumentException.
     */
    public static FlatBVH read(ByteBuffer in) {
        requireLittleEndian(in);
        int count = in.getInt();
        int primitives = in.getInt();
        if (count < 0 || primitives < 1 || 4L * (BvhNodes.BOUNDS_PER_NODE + BvhNodes.CHILDREN_PER_NODE) * count
                                           + 4L * primitives > in.remaining()) {
            throw new IllegalArgumentException("a BVH of " + count + " nodes over " + primitives + " primitives does not fit");
        }
        BvhNodes nodes = new BvhNodes(count);
        in.asFloatBuffer().get(nodes.bounds);
        in.position(in.position() + 4 * nodes.bounds.length);
        in.asIntBuffer().get(nodes.children);
        in.position(in.position() + 4 * nodes.children.length);
        int[] order = new int[primitives];
        in.asIntBuffer().get(order);
        in.position(in.position() + 4 * primitives);
        float[] rootBox = new float[6];
        for (int k = 0; k < 6; k++) {
            rootBox[k] = in.getFloat();
        }
        int rootLink = in.getInt();
        int rootCount = in.getInt();
        checkChild(rootLink, rootCount, count, primitives);
        for (int node = 0; node < count; node++) {
            for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
                checkChild(nodes.link(node, side), nodes.primitiveCount(node, side), count, primitives);
            }
        }
        return new FlatBVH(nodes, order, rootBox, rootLink, rootCount);
    }

    /** An interior child links to a node; a leaf to a run of the leaf order. */
    private static void checkChild(int link, int primitiveCount, int nodes, int primitives) {
        boolean valid = primitiveCount == 0 ? link >= 0 && link < nodes
                                            : primitiveCount > 0 && link >= 0 && link <= primitives - primitiveCount;
        if (!valid) {
            throw new IllegalArgumentException("a BVH child links to " + link + " with " + primitiveCount
                                               + " primitives, outside the " + nodes + " nodes and " + primitives + " primitives");
        }
    }

    private static void requireLittleEndian(ByteBuffer buffer) {
        if (buffer.order() != ByteOrder.LITTLE_ENDIAN) {
            throw new IllegalArgumentException("BVH bytes are little-endian");
        }
    }
}

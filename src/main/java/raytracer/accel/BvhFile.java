package raytracer.accel;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * A {@link FlatBVH} in bytes, for the mesh cache: the arrays of {@link BvhNodes}, the leaf order and
 * the root, each copied in bulk (little-endian, the order of the machines this runs on, so the
 * copies are plain memory copies), through a {@link Sink} and back from a {@link Source}, which
 * the mesh cache streams through a small buffer, or a ByteBuffer.
 *
 * <pre>
 *   int nodes, int primitives
 *   float[12 nodes] bounds, int[4 nodes] children, int[primitives] order
 *   float[6] root box, int root link, int root count
 * </pre>
 *
 * A tree without an order ({@link FlatBVH#inLeafOrder}) writes {@code -primitives} and no order.
 *
 * <p><b>Whoever changes the layout of {@link BvhNodes} or {@link FlatBVH} (what an array holds,
 * their order, a new field) must change it here and add 1 to {@link #VERSION}</b>: a cache written
 * by another version is then rebuilt rather than misread. Version 3 keeps version 2's layout: it
 * came with the parallel binned SAH builder, so that trees the serial SAH builder cached are built
 * again.
 */
public final class BvhFile {
    /** The layout above; the mesh cache keys its files by it. */
    public static final int VERSION = 3;

    /** Where the bytes go: little-endian values, arrays in bulk. */
    public interface Sink {
        void putInt(int value);

        void putInts(int[] values);

        void putFloats(float[] values);
    }

    /** Where the bytes come from, as a {@link Sink} wrote them. */
    public interface Source {
        int getInt();

        void getInts(int[] into);

        void getFloats(float[] into);

        /** Bytes left to read. */
        long remaining();
    }

    private BvhFile() {
    }

    /** The bytes {@link #write} takes for {@code bvh}. */
    public static long size(FlatBVH bvh) {
        int order = bvh.order == null ? 0 : bvh.order.length;
        return 4L * (2 + bvh.nodes.bounds.length + bvh.nodes.children.length + order + 6 + 2);
    }

    /** Writes {@code bvh} at {@code out}'s position, which it advances; {@code out} is little-endian. */
    public static void write(FlatBVH bvh, ByteBuffer out) {
        requireLittleEndian(out);
        write(bvh, sink(out));
    }

    public static void write(FlatBVH bvh, Sink out) {
        out.putInt(bvh.nodes.count());
        out.putInt(bvh.order == null ? -bvh.primitiveCount() : bvh.primitiveCount());
        out.putFloats(bvh.nodes.bounds);
        out.putInts(bvh.nodes.children);
        if (bvh.order != null) {
            out.putInts(bvh.order);
        }
        out.putFloats(bvh.rootBox);
        out.putInt(bvh.rootLink);
        out.putInt(bvh.rootCount);
    }

    /**
     * Reads a tree written by {@link #write} from {@code in}'s position, which it advances. Links
     * and counts are checked against the arrays, so that no traversal can leave them; a tree that
     * fails is an IllegalArgumentException.
     */
    public static FlatBVH read(ByteBuffer in) {
        requireLittleEndian(in);
        return read(source(in));
    }

    public static FlatBVH read(Source in) {
        int count = in.getInt();
        int written = in.getInt();
        boolean inLeafOrder = written < 0;
        int primitives = inLeafOrder ? -written : written;
        if (count < 0 || written == 0 || written == Integer.MIN_VALUE
            || 4L * (BvhNodes.BOUNDS_PER_NODE + BvhNodes.CHILDREN_PER_NODE) * count + (inLeafOrder ? 0 : 4L * primitives)
               > in.remaining()) {
            throw new IllegalArgumentException("a BVH of " + count + " nodes over " + written + " primitives does not fit");
        }
        BvhNodes nodes = new BvhNodes(count);
        in.getFloats(nodes.bounds);
        in.getInts(nodes.children);
        int[] order = null;
        if (!inLeafOrder) {
            order = new int[primitives];
            in.getInts(order);
        }
        float[] rootBox = new float[6];
        in.getFloats(rootBox);
        int rootLink = in.getInt();
        int rootCount = in.getInt();
        checkChild(rootLink, rootCount, count, primitives);
        if (rootCount == 0 && rootLink != 0) {
            throw new IllegalArgumentException("a BVH's root is node 0, not " + rootLink);
        }
        checkNodes(nodes, primitives);
        return new FlatBVH(nodes, order, primitives, rootBox, rootLink, rootCount);
    }

    private static Sink sink(ByteBuffer out) {
        return new Sink() {
            @Override
            public void putInt(int value) {
                out.putInt(value);
            }

            @Override
            public void putInts(int[] values) {
                out.asIntBuffer().put(values);
                out.position(out.position() + 4 * values.length);
            }

            @Override
            public void putFloats(float[] values) {
                out.asFloatBuffer().put(values);
                out.position(out.position() + 4 * values.length);
            }
        };
    }

    private static Source source(ByteBuffer in) {
        return new Source() {
            @Override
            public int getInt() {
                return in.getInt();
            }

            @Override
            public void getInts(int[] into) {
                in.asIntBuffer().get(into);
                in.position(in.position() + 4 * into.length);
            }

            @Override
            public void getFloats(float[] into) {
                in.asFloatBuffer().get(into);
                in.position(in.position() + 4 * into.length);
            }

            @Override
            public long remaining() {
                return in.remaining();
            }
        };
    }

    /**
     * Every child is a leaf within the leaf order or a node after its parent (the depth-first
     * numbering, so the links make no cycle) at most {@link FlatBVH#MAX_DEPTH} deep: no traversal
     * leaves the arrays, loops, or outgrows its stack.
     */
    private static void checkNodes(BvhNodes nodes, int primitives) {
        int count = nodes.count();
        int[] depth = new int[count];
        for (int node = 0; node < count; node++) {
            for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
                int link = nodes.link(node, side);
                int children = nodes.primitiveCount(node, side);
                checkChild(link, children, count, primitives);
                if (children == 0) {
                    if (link <= node || depth[node] + 1 >= FlatBVH.MAX_DEPTH) {
                        throw new IllegalArgumentException("node " + node + " links to node " + link
                                                           + ", not a node after it within " + FlatBVH.MAX_DEPTH + " levels");
                    }
                    depth[link] = depth[node] + 1;
                }
            }
        }
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

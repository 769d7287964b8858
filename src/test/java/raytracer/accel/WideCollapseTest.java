package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A binary tree collapsed into four-wide nodes keeps its leaves, in the same order, with the same
 * boxes; every wide node has two lanes at least, its lanes in use first, and fewer than four only
 * when all it holds are leaves (an interior child would have been opened); and the wide tree is
 * no deeper than the binary one.
 */
class WideCollapseTest {

    @Test
    void theLeavesOfMedianAndSahTreesSurviveTheCollapse() {
        float[] boxes = MeshBVH.triangleBoxes(MeshBVHTest.soup(7_001, 3));
        for (BinaryTree binary : new BinaryTree[] {new MedianSplitBuilder(4).binary(boxes.clone(), null),
                                                   new MedianSplitBuilder(1).binary(boxes.clone(), null),
                                                   new SahBuilder(4).binary(boxes.clone(), null)}) {
            List<float[]> expected = new ArrayList<>();
            binaryLeaves(binary.nodes(), binary.rootLink(), expected);
            FlatBVH wide = binary.collapsed();
            List<float[]> actual = new ArrayList<>();
            int depth = wideLeaves(wide.nodes, 0, actual);
            assertEquals(expected.size(), actual.size(), "leaves");
            for (int i = 0; i < expected.size(); i++) {
                assertArrayEquals(expected.get(i), actual.get(i), "leaf " + i + ": link, count and box");
            }
            assertArrayEquals(binary.order(), wide.order);
            assertTrue(depth <= binaryDepth(binary.nodes(), binary.rootLink()));
            assertEquals(depth + 1, wide.depth());
        }
    }

    /** Leaves left to right as (link, count, box), float-coded. */
    private static void binaryLeaves(BvhNodes nodes, int node, List<float[]> out) {
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            int count = nodes.primitiveCount(node, side);
            if (count > 0) {
                float[] leaf = new float[8];
                leaf[0] = nodes.link(node, side);
                leaf[1] = count;
                System.arraycopy(nodes.bounds, BvhNodes.boxAt(node, side), leaf, 2, 6);
                out.add(leaf);
            } else {
                binaryLeaves(nodes, nodes.link(node, side), out);
            }
        }
    }

    /** Leaves left to right, checking the lanes; returns the depth of interior nodes below and at {@code node}. */
    private static int wideLeaves(WideNodes nodes, int node, List<float[]> out) {
        int lanes = 0;
        boolean interior = false;
        int deepest = 0;
        for (int lane = 0; lane < WideNodes.WIDTH; lane++) {
            int count = nodes.primitiveCount(node, lane);
            if (count == WideNodes.EMPTY) {
                continue;
            }
            assertEquals(lanes++, lane, "lanes in use come first");
            if (count > 0) {
                float[] leaf = new float[8];
                leaf[0] = nodes.link(node, lane);
                leaf[1] = count;
                System.arraycopy(nodes.box(node, lane), 0, leaf, 2, 6);
                out.add(leaf);
            } else {
                interior = true;
                assertTrue(nodes.link(node, lane) > node, "children are numbered after their parent");
                deepest = Math.max(deepest, wideLeaves(nodes, nodes.link(node, lane), out));
            }
        }
        assertTrue(lanes >= 2);
        assertTrue(lanes == WideNodes.WIDTH || !interior, "a node with a free lane holds only leaves");
        return 1 + deepest;
    }

    private static int binaryDepth(BvhNodes nodes, int node) {
        int deepest = 0;
        for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
            if (nodes.primitiveCount(node, side) == 0) {
                deepest = Math.max(deepest, binaryDepth(nodes, nodes.link(node, side)));
            }
        }
        return 1 + deepest;
    }
}

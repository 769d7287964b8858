package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Tree equality for the builder tests: node for node, and the same leaf order, binary trees or wide. */
final class BvhAssertions {
    private BvhAssertions() {
    }

    static void assertSameTree(FlatBVH expected, FlatBVH actual) {
        assertEquals(expected.nodeCount(), actual.nodeCount(), "node count");
        assertSameBounds(expected.rootBox, actual.rootBox, "root box");
        assertEquals(expected.rootLink, actual.rootLink, "root link");
        assertEquals(expected.rootCount, actual.rootCount, "root count");
        assertArrayEquals(expected.order, actual.order, "leaf order");
        assertArrayEquals(expected.nodes.children, actual.nodes.children, "children's links and counts");
        assertSameBounds(expected.nodes.bounds, actual.nodes.bounds, "children's boxes");
    }

    static void assertSameTree(BinaryTree expected, BinaryTree actual) {
        assertEquals(expected.nodes().count(), actual.nodes().count(), "node count");
        assertSameBounds(expected.rootBox(), actual.rootBox(), "root box");
        assertEquals(expected.rootLink(), actual.rootLink(), "root link");
        assertEquals(expected.rootCount(), actual.rootCount(), "root count");
        assertArrayEquals(expected.order(), actual.order(), "leaf order");
        assertArrayEquals(expected.nodes().children, actual.nodes().children, "children's links and counts");
        assertSameBounds(expected.nodes().bounds, actual.nodes().bounds, "children's boxes");
    }

    /**
     * Equal as numbers: a union over the same boxes taken in another order may keep a plane at
     * -0.0 where the other keeps 0.0, and both are the same plane.
     */
    private static void assertSameBounds(float[] expected, float[] actual, String what) {
        assertEquals(expected.length, actual.length, what + ": length");
        for (int i = 0; i < expected.length; i++) {
            float e = expected[i];
            float a = actual[i];
            assertTrue(e == a, () -> what + " differ at " + e + " != " + a);
        }
    }
}

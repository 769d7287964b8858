package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.junit.jupiter.api.Test;
import raytracer.shapes.mesh.Mesh;

/** A tree written by BvhFile reads back array for array, and a tree whose links leave its arrays is refused. */
class BvhFileTest {
    private static ByteBuffer written(FlatBVH bvh) {
        ByteBuffer buffer = ByteBuffer.allocate((int) BvhFile.size(bvh) + 16).order(ByteOrder.LITTLE_ENDIAN);
        buffer.position(8); // anywhere in a larger file
        BvhFile.write(bvh, buffer);
        assertEquals(8 + BvhFile.size(bvh), buffer.position(), "size() is what write() takes");
        buffer.position(8);
        return buffer;
    }

    @Test
    void aTreeReadsBackExactly() {
        Mesh mesh = Icosphere.make(3);
        for (FlatBVH bvh : new FlatBVH[] {new MedianSplitBuilder(8).build(MeshBVH.triangleBoxes(mesh)),
                                          new SahBuilder(4).build(MeshBVH.triangleBounds(mesh))}) {
            ByteBuffer buffer = written(bvh);
            FlatBVH read = BvhFile.read(buffer);
            assertEquals(8 + BvhFile.size(bvh), buffer.position());
            assertArrayEquals(bvh.nodes.bounds, read.nodes.bounds);
            assertArrayEquals(bvh.nodes.children, read.nodes.children);
            assertArrayEquals(bvh.order, read.order);
            assertArrayEquals(bvh.rootBox, read.rootBox);
            assertEquals(bvh.rootLink, read.rootLink);
            assertEquals(bvh.rootCount, read.rootCount);
        }
    }

    @Test
    void linksOutsideTheArraysAreRefused() {
        FlatBVH bvh = new MedianSplitBuilder(8).build(MeshBVH.triangleBoxes(Icosphere.make(2)));
        assertTrue(bvh.nodes.count() > 1);
        ByteBuffer buffer = written(bvh);
        // the first node's left child made a leaf running past the leaf order
        int at = 8 + 8 + 4 * bvh.nodes.bounds.length;
        buffer.putInt(at, bvh.order.length - 1);
        buffer.putInt(at + 4, 2);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> BvhFile.read(buffer));
        assertTrue(e.getMessage().contains("outside"), e.getMessage());
        // or an interior node linking back to the root, a cycle a traversal would never leave
        ByteBuffer cycle = written(bvh);
        assertEquals(0, bvh.nodes.primitiveCount(1, BvhNodes.LEFT), "node 1 has an interior left child");
        cycle.putInt(at + 4 * BvhNodes.CHILDREN_PER_NODE, 0);
        e = assertThrows(IllegalArgumentException.class, () -> BvhFile.read(cycle));
        assertTrue(e.getMessage().contains("not a node after it"), e.getMessage());
        ByteBuffer bigEndian = ByteBuffer.allocate(64);
        assertThrows(IllegalArgumentException.class, () -> BvhFile.read(bigEndian));
    }
}

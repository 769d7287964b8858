package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static raytracer.accel.BvhAssertions.assertSameTree;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.TestAssets;
import raytracer.shapes.mesh.Mesh;

/**
 * The parallel median build gives the serial build's tree, array for array: each parallel task
 * writes the nodes whose numbers its subtree's size fixes in advance.
 */
class MedianSplitBuilderTest {

    private static void assertParallelEqualsSerial(float[] boxes, int leafSize, int threshold) {
        FlatBVH serial = new MedianSplitBuilder(leafSize, Integer.MAX_VALUE).build(boxes.clone());
        FlatBVH parallel = new MedianSplitBuilder(leafSize, threshold).build(boxes.clone());
        assertSameTree(serial, parallel);
    }

    /** Thresholds down to the smallest allowed (twice the leaf size) split the soup into hundreds of tasks. */
    @ParameterizedTest
    @CsvSource({"1, 0", "1, 100", "4, 0", "4, 1000", "8, 0", "8, 5000", "3, 777"})
    void parallelBuildOfATriangleSoupEqualsTheSerialBuild(int leafSize, int threshold) {
        float[] boxes = MeshBVH.triangleBoxes(MeshBVHTest.soup(20_011, 17));
        assertParallelEqualsSerial(boxes, leafSize, threshold);
    }

    @Test
    void parallelBuildOfAMeshEqualsTheSerialBuild() {
        Mesh sphere = Icosphere.make(5); // 20,480 triangles, many with equal centroid coordinates
        assertParallelEqualsSerial(MeshBVH.triangleBoxes(sphere), 8, 0);
        assertParallelEqualsSerial(MeshBVH.triangleBoxes(sphere), 2, 300);
    }

    /** The bunny (69,451 triangles) is above the default threshold, so the public builder goes parallel. */
    @Test
    void defaultBuilderOnTheBunnyEqualsTheSerialBuild() throws ObjException {
        Mesh bunny = ObjLoader.load(TestAssets.path("meshes/stanford-bunny.obj.gz"), false).mesh();
        float[] boxes = MeshBVH.triangleBoxes(bunny);
        FlatBVH serial = new MedianSplitBuilder(8, Integer.MAX_VALUE).build(boxes.clone());
        assertSameTree(serial, new MedianSplitBuilder(8).build(boxes.clone()));
    }

    @Test
    void repeatedParallelBuildsAreIdentical() {
        float[] boxes = MeshBVH.triangleBoxes(MeshBVHTest.soup(50_000, 23));
        FlatBVH first = new MedianSplitBuilder(4, 0).build(boxes.clone());
        for (int i = 0; i < 3; i++) {
            assertSameTree(first, new MedianSplitBuilder(4, 0).build(boxes.clone()));
        }
    }

    /**
     * A mesh's triangle array carried through the build comes out in the leaf order, and
     * the tree is the one built without it, serially and in parallel.
     */
    @Test
    void carriedTrianglesComeOutInTheLeafOrder() {
        Mesh sphere = Icosphere.make(5);
        for (int threshold : new int[] {Integer.MAX_VALUE, 0, 300}) {
            FlatBVH plain = new MedianSplitBuilder(8, threshold).build(MeshBVH.triangleBoxes(sphere));
            int[] carried = sphere.triangles().clone();
            FlatBVH carrying = new MedianSplitBuilder(8, threshold).build(MeshBVH.triangleBoxes(sphere), carried);
            assertSameTree(plain, carrying);
            int[] expected = new int[carried.length];
            for (int k = 0; k < plain.primitiveCount(); k++) {
                System.arraycopy(sphere.triangles(), 3 * plain.order[k], expected, 3 * k, 3);
            }
            assertArrayEquals(expected, carried);
        }
    }
}

package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static raytracer.accel.BvhAssertions.assertSameTree;

import java.nio.file.Path;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.shapes.mesh.Mesh;

/**
 * The report's sorted-median split, as written, on a case worked by hand; and the fast builder,
 * which selects medians instead of sorting, shown to build the same tree: the same nodes, boxes,
 * links and counts, and the same leaf order.
 */
class SortedMedianBuilderTest {

    /** A unit cube per primitive, its low corner at (x, y, z). */
    private static float[] cubes(double... corners) {
        float[] boxes = new float[2 * corners.length];
        for (int i = 0; i < corners.length / 3; i++) {
            for (int k = 0; k < 3; k++) {
                boxes[6 * i + k] = (float) corners[3 * i + k];
                boxes[6 * i + 3 + k] = (float) corners[3 * i + k] + 1;
            }
        }
        return boxes;
    }

    /**
     * Eight cubes on a row along x, given out of order: the root sorts them by x and splits 4 + 4,
     * each half (now longest along x too) 2 + 2, into leaves of two, listed left to right.
     */
    @Test
    void aRowOfCubesIsSortedAndHalvedAlongItsLength() {
        double[] xs = {5, 0, 7, 2, 6, 1, 3, 4}; // primitive i sits at x = xs[i]
        double[] corners = new double[24];
        for (int i = 0; i < 8; i++) {
            corners[3 * i] = 2 * xs[i];
        }
        BinaryTree tree = new SortedMedianBuilder(2).binary(cubes(corners));
        assertArrayEquals(new int[] {1, 5, 3, 6, 7, 0, 4, 2}, tree.order(), "primitives by x");
        assertEquals(3, tree.nodes().count(), "three interior nodes over four leaves");
        assertEquals(0, tree.rootCount(), "the root is an interior node");
        BvhNodes nodes = tree.nodes();
        // node 0 is the root, 1 its left child (x from 0 to 7), 2 its right child (x from 8 to 15)
        assertEquals(1, nodes.link(0, BvhNodes.LEFT));
        assertEquals(2, nodes.link(0, BvhNodes.RIGHT));
        assertEquals(0f, nodes.bounds[BvhNodes.boxAt(0, BvhNodes.LEFT)]);
        assertEquals(7f, nodes.bounds[BvhNodes.boxAt(0, BvhNodes.LEFT) + 3]);
        assertEquals(8f, nodes.bounds[BvhNodes.boxAt(0, BvhNodes.RIGHT)]);
        assertEquals(15f, nodes.bounds[BvhNodes.boxAt(0, BvhNodes.RIGHT) + 3]);
        for (int node = 1; node <= 2; node++) {
            for (int side = BvhNodes.LEFT; side <= BvhNodes.RIGHT; side++) {
                int leaf = 2 * (node - 1) + side; // the leaves, left to right
                assertEquals(2, nodes.primitiveCount(node, side), "a leaf of two");
                assertEquals(2 * leaf, nodes.link(node, side), "the leaf's run of the order");
                assertEquals(4f * leaf, nodes.bounds[BvhNodes.boxAt(node, side)], "the leaf's box starts at its first cube");
            }
        }
        // flat, the same nodes: the median builders number them depth-first already
        assertSameTree(tree.flat(), new SortedMedianBuilder(2).build(cubes(corners)));
    }

    /** Equal centroids go by primitive id: identical boxes come out in id order. */
    @Test
    void tiesAreBrokenByPrimitiveId() {
        double[] corners = new double[3 * 9];
        FlatBVH tree = new SortedMedianBuilder(2).build(cubes(corners));
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5, 6, 7, 8}, tree.order);
        assertSameTree(tree, new MedianSplitBuilder(2).build(cubes(corners)));
    }

    private static void assertFastBuildIsTheSortedBuild(float[] boxes, int leafSize) {
        BinaryTree sorted = new SortedMedianBuilder(leafSize).binary(boxes.clone());
        assertSameTree(sorted, new MedianSplitBuilder(leafSize, Integer.MAX_VALUE).binary(boxes.clone(), null));
        assertSameTree(sorted, new MedianSplitBuilder(leafSize, 0).binary(boxes.clone(), null)); // in parallel tasks
    }

    /**
     * Soups of sizes that leave, above the leaves, nodes of up to 12 primitives (which the
     * selection ends by sorting) and of 14 to 24 (which it leaves partitioned, not sorted).
     */
    @ParameterizedTest
    @CsvSource({"1, 5003", "2, 5003", "4, 5003", "8, 5003", "8, 4096", "7, 3584", "12, 6000"})
    void onATriangleSoup(int leafSize, int triangles) {
        assertFastBuildIsTheSortedBuild(MeshBVH.triangleBoxes(MeshBVHTest.soup(triangles, 29)), leafSize);
    }

    /** An icosphere's triangles share many centroid coordinates: the ties must go the same way. */
    @ParameterizedTest
    @ValueSource(ints = {1, 4, 8})
    void onAnIcosphere(int leafSize) {
        assertFastBuildIsTheSortedBuild(MeshBVH.triangleBoxes(Icosphere.make(4)), leafSize);
    }

    /** The Spot cow of the scenes (5,856 triangles). */
    @ParameterizedTest
    @ValueSource(ints = {2, 8})
    void onTheSpotMesh(int leafSize) throws ObjException {
        Mesh spot = ObjLoader.load(Path.of("assets/spot/spot_quadrangulated.obj"), false).mesh();
        assertFastBuildIsTheSortedBuild(MeshBVH.triangleBoxes(spot), leafSize);
    }

    /** Cubes on a coarse grid: whole layers tie on every axis, over ranges long enough for the windowed selection. */
    @Test
    void onAGridOfCubesWithManyTies() {
        SplittableRandom r = new SplittableRandom(41);
        double[] corners = new double[3 * 4000];
        for (int i = 0; i < corners.length; i++) {
            corners[i] = r.nextInt(6);
        }
        assertFastBuildIsTheSortedBuild(cubes(corners), 3);
    }

    /** Boxes given as doubles are rounded outward the same way by both. */
    @Test
    void onObjectBoundsGivenAsDoubles() {
        double[] bounds = MeshBVH.triangleBounds(MeshBVHTest.soup(3_001, 31));
        assertSameTree(new SortedMedianBuilder(2).build(bounds), new MedianSplitBuilder(2, 0).build(bounds));
    }
}

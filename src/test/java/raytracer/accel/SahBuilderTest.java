package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.accel.BvhAssertions.assertSameTree;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.TestAssets;
import raytracer.shapes.mesh.Mesh;

/**
 * The binned SAH builder: its root split is the cheapest plane between bins, recomputed here by
 * brute force over the primitives; a parallel build is the serial build, array for array; carried
 * vertex indices come out in the leaf order; and on the bunny its tree is expected to cost a ray
 * much less than the median tree's.
 */
class SahBuilderTest {

    @ParameterizedTest
    @CsvSource({"1, 0", "4, 100", "4, 1000", "8, 5000", "2, 777"})
    void parallelBuildOfATriangleSoupEqualsTheSerialBuild(int leafSize, int threshold) {
        float[] boxes = MeshBVH.triangleBoxes(MeshBVHTest.soup(20_011, 17));
        BinaryTree serial = new SahBuilder(leafSize, Integer.MAX_VALUE).binary(boxes.clone(), null);
        assertSameTree(serial, new SahBuilder(leafSize, threshold).binary(boxes.clone(), null));
    }

    /** An icosphere's triangles share many centroid coordinates, and a grid of equal cubes has nothing to bin. */
    @Test
    void parallelBuildsWithTiesAndCoincidentCentroidsEqualTheSerialBuild() {
        float[] sphere = MeshBVH.triangleBoxes(Icosphere.make(5));
        assertSameTree(new SahBuilder(4, Integer.MAX_VALUE).binary(sphere.clone(), null),
                       new SahBuilder(4, 300).binary(sphere.clone(), null));
        float[] same = new float[6 * 5000];
        for (int i = 0; i < 5000; i++) {
            same[6 * i + 3] = 1;
            same[6 * i + 4] = 1;
            same[6 * i + 5] = 1;
        }
        BinaryTree serial = new SahBuilder(4, Integer.MAX_VALUE).binary(same.clone(), null);
        assertSameTree(serial, new SahBuilder(4, 100).binary(same.clone(), null));
        assertTrue(serial.flat().depth() < FlatBVH.MAX_DEPTH, "equal boxes are halved, not peeled one by one");
    }

    @Test
    void carriedTrianglesComeOutInTheLeafOrder() {
        Mesh sphere = Icosphere.make(5);
        for (int threshold : new int[] {Integer.MAX_VALUE, 300}) {
            int[] carried = sphere.triangles().clone();
            BinaryTree plain = new SahBuilder(4, threshold).binary(MeshBVH.triangleBoxes(sphere), null);
            BinaryTree carrying = new SahBuilder(4, threshold).binary(MeshBVH.triangleBoxes(sphere), carried);
            assertSameTree(plain, carrying);
            int[] expected = new int[carried.length];
            for (int k = 0; k < plain.order().length; k++) {
                System.arraycopy(sphere.triangles(), 3 * plain.order()[k], expected, 3 * k, 3);
            }
            assertArrayEquals(expected, carried);
        }
    }

    /**
     * The root's two children split the primitives where N_L A_L + N_R A_R is least among the
     * planes between bins, equal slices of the root's box along its longest axis, each side's box
     * the union of its primitives' boxes: recomputed over the primitives themselves.
     */
    @Test
    void theRootSplitIsTheCheapestPlaneBetweenBins() {
        float[] boxes = MeshBVH.triangleBoxes(MeshBVHTest.soup(10_000, 5));
        BinaryTree tree = new SahBuilder(4).binary(boxes.clone(), null);
        int n = boxes.length / 6;
        float[] box = new float[6];
        FloatBoxes.union(boxes, 0, n, box, 0);
        int axis = FloatBoxes.longestAxis(box, 0);
        // the builder's bins, slices of the root's box along its longest axis, in centroid keys
        // (twice the centroid); the same float arithmetic (SahBins.bin) decides where a centroid falls
        float lo = 2 * box[axis];
        float scale = SahBins.BINS * 0.99999f / (2 * box[3 + axis] - lo);
        double best = Double.POSITIVE_INFINITY;
        int bestPlane = -1;
        for (int plane = 1; plane < SahBins.BINS; plane++) {
            float[] sides = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                             Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY,
                             Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                             Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
            int left = 0;
            for (int i = 0; i < n; i++) {
                boolean isLeft = SahBins.bin(FloatBoxes.centroidKey(boxes, i, axis), lo, scale, SahBins.BINS - 1) < plane;
                left += isLeft ? 1 : 0;
                int at = isLeft ? 0 : 6;
                for (int k = 0; k < 3; k++) {
                    sides[at + k] = Math.min(sides[at + k], boxes[6 * i + k]);
                    sides[at + 3 + k] = Math.max(sides[at + 3 + k], boxes[6 * i + 3 + k]);
                }
            }
            double cost = left * SahBins.halfArea(sides, 0) + (n - left) * SahBins.halfArea(sides, 6);
            if (cost < best) {
                best = cost;
                bestPlane = plane;
            }
        }
        // the left child holds positions 0 .. mid - 1, and the right child links to mid: as a leaf
        // to its first position, as a node to its number, 0 + mid (a subtree over c primitives
        // numbers c - 1 nodes)
        BvhNodes nodes = tree.nodes();
        int mid = nodes.link(0, BvhNodes.RIGHT);
        double built = mid * SahBins.halfArea(nodes.bounds, BvhNodes.boxAt(0, BvhNodes.LEFT))
                       + (n - mid) * SahBins.halfArea(nodes.bounds, BvhNodes.boxAt(0, BvhNodes.RIGHT));
        assertEquals(best, built, 1e-9 * best, "the root's split costs what the cheapest plane (" + bestPlane + ") costs");
    }

    /** The SAH tree of the bunny is expected to test fewer triangles per ray than the median tree by far. */
    @Test
    void onTheBunnyTheSahTreeCostsLessThanTheMedianTree() throws ObjException {
        Mesh bunny = ObjLoader.load(TestAssets.path("meshes/stanford-bunny.obj.gz"), false).mesh();
        SahCost median = SahCost.of(new MedianSplitBuilder(8).build(MeshBVH.triangleBoxes(bunny)));
        SahCost sah = SahCost.of(new SahBuilder(4).build(MeshBVH.triangleBoxes(bunny)));
        assertTrue(sah.cost() < 0.75 * median.cost(), "SAH " + sah + ", median " + median);
        assertTrue(sah.primitiveTests() < 0.5 * median.primitiveTests(), "SAH " + sah + ", median " + median);
    }
}

package raytracer.accel;

import raytracer.math.SlabRay;

/**
 * The test of a wide node's four boxes ({@link WideNodes}) against a ray: for each lane i, the
 * bits of the distance at which the ray enters the box ({@link SlabRay#entryBits}, +infinity's
 * bits for a miss) with the two lowest bits replaced by i, written to {@code keys[i]}. Sorting the
 * keys sorts the lanes by entry, misses last; clearing the two bits gives an entry a few ulps
 * nearer at most. Two implementations give the same bits: lane by lane in plain Java
 * ({@link ScalarNodeTest}), and four lanes at once with the Vector API where a JDK that has it runs
 * the renderer with the module added ({@link #CHOSEN}).
 */
interface NodeTest {
    /** The test the traversal uses: chosen once, at start-up. */
    NodeTest CHOSEN = choose();

    void keys(SlabRay ray, float[] bounds, int at, long tMaxBits, long[] keys);

    /** A name for statistics: "scalar" or "vector". */
    String name();

    /**
     * The Vector API's test when the module jdk.incubator.vector is in the boot layer (a JDK 25
     * started with --add-modules jdk.incubator.vector, as tools/render does) and its class loads,
     * else the scalar one; -Draytracer.nodeTest=scalar forces the scalar one (to compare them).
     * The vector class is compiled for JDK 25 apart from the rest (build.gradle, source set
     * "vector") and only ever loaded here, so that JDK 17 never reads it.
     */
    private static NodeTest choose() {
        boolean vectorModule = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();
        if (vectorModule && !"scalar".equals(System.getProperty("raytracer.nodeTest"))) {
            try {
                return (NodeTest) Class.forName("raytracer.accel.VectorNodeTest").getDeclaredConstructor().newInstance();
            } catch (ReflectiveOperationException | LinkageError e) {
                // not in this jar, or built for another JDK: the scalar test gives the same bits
            }
        }
        return new ScalarNodeTest();
    }
}

package raytracer.accel;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import raytracer.io.obj.ObjLoader;
import raytracer.shapes.mesh.Mesh;

/**
 * The builders side by side on a mesh (tools/studies/bvh/README.md): build time, the packing of the
 * nodes included (the median of several builds after the first, on the common pool), and the
 * expected tests per ray by the surface area heuristic ({@link SahCost}) of the tree as built and
 * as packed (the same tree: a check).
 *
 * <pre>
 *   java -cp build/classes/java/main:build/classes/java/jmh:build/libs/render.jar raytracer.accel.BvhStudy \
 *        assets/meshes/stanford-dragon.obj.gz [rounds] [builder ...]
 * </pre>
 *
 * Builders are "median N", "sah N" (the parallel binned SAH) and "serial-sah N" (the SAH builder it
 * replaced), N the leaf size. -Dcpu=true builds serially and times the thread's CPU time, which a
 * shared machine disturbs less than the wall time.
 */
public final class BvhStudy {
    private static final boolean CPU = Boolean.getBoolean("cpu");
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private BvhStudy() {
    }

    public static void main(String[] args) throws Exception {
        Mesh mesh = ObjLoader.load(Path.of(args[0]), false).mesh();
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 5;
        String[] names = args.length > 2 ? Arrays.copyOfRange(args, 2, args.length) : new String[] {"median 8", "sah 4", "serial-sah 4"};
        System.out.printf(Locale.ROOT, "%s: %d triangles, %s%n", args[0], mesh.triangleCount(), CPU ? "serial, CPU time" : "wall time");
        for (String name : names) {
            long[] times = new long[rounds];
            BinaryTree binary = null;
            FlatBVH flat = null;
            for (int r = 0; r < rounds; r++) {
                long start = now();
                binary = build(name, mesh);
                flat = binary.flat();
                times[r] = now() - start;
            }
            long first = times[0];
            Arrays.sort(times, 1, rounds);
            SahCost b = SahCost.of(binary);
            SahCost w = SahCost.of(flat);
            System.out.printf(Locale.ROOT, "%-14s build %.3f s (median of %d after the first, %.3f s); depth %d; "
                              + "binary: box %.1f, primitive %.2f, cost %.2f; flat (%d nodes): box %.1f, primitive %.2f, cost %.2f%n",
                              name, times[1 + (rounds - 1) / 2] / 1e9, rounds - 1, first / 1e9, flat.depth(),
                              b.boxTests(), b.primitiveTests(), b.cost(), flat.nodeCount(), w.boxTests(), w.primitiveTests(), w.cost());
        }
    }

    private static long now() {
        return CPU ? THREADS.getCurrentThreadCpuTime() : System.nanoTime();
    }

    private static BinaryTree build(String name, Mesh mesh) {
        int leaf = Integer.parseInt(name.substring(name.lastIndexOf(' ') + 1));
        int threshold = CPU ? Integer.MAX_VALUE : 32_768;
        if (name.startsWith("median")) {
            return new MedianSplitBuilder(leaf, threshold).binary(MeshBVH.triangleBoxes(mesh), mesh.triangles().clone());
        }
        if (name.startsWith("nocarry-sah")) {
            return new SahBuilder(leaf, threshold).binary(MeshBVH.triangleBoxes(mesh), null);
        }
        if (name.startsWith("sah")) {
            return new SahBuilder(leaf, threshold).binary(MeshBVH.triangleBoxes(mesh), mesh.triangles().clone());
        }
        return new SerialSahBuilder(leaf).binary(MeshBVH.triangleBounds(mesh));
    }
}

package raytracer.accel;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.io.obj.ObjLoader;
import raytracer.io.scene.SceneLoader;
import raytracer.math.MutableVec3;
import raytracer.math.Ray;
import raytracer.shapes.mesh.Mesh;

/**
 * The box and triangle tests a bench frame's rays make in its mesh, per builder
 * (tools/studies/bvh/README.md): the renderer's {@code --stats} counts box tests only, and a
 * counter of triangle tests in the traversal itself would cost every render. The frame's rays
 * (every third pixel's primary ray in x and y, the shadow rays to its lights from the hits, as
 * FrameRaysBenchmark makes them) are traced through each tree of the mesh alone, a leaf's triangles counted one by
 * one as they are tested; the mesh is untransformed in the bench scenes, so the scene's rays are
 * the mesh's.
 *
 * <pre>
 *   java -cp build/classes/java/main:build/classes/java/jmh:build/libs/render.jar raytracer.accel.FrameTests \
 *        scenes/bench-dragon.yaml assets/meshes/stanford-dragon.obj.gz ["median 8" "sah 4" ...]
 * </pre>
 */
public final class FrameTests {
    private FrameTests() {
    }

    public static void main(String[] args) throws Exception {
        World world = SceneLoader.load(Path.of(args[0])).world();
        world.prepare(objects -> Aggregation.organize(objects, Aggregation.Mode.AUTO));
        Mesh mesh = ObjLoader.load(Path.of(args[1]), false).mesh();
        List<double[]> rays = frameRays(world);
        String[] names = args.length > 2 ? java.util.Arrays.copyOfRange(args, 2, args.length) : new String[] {"median 8", "sah 4"};
        System.out.printf(Locale.ROOT, "%s: %d triangles; %d primary, %d shadow rays%n", args[1], mesh.triangleCount(),
                          rays.get(0).length / 6, rays.get(1).length / 7);
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        for (String name : names) {
            int leaf = Integer.parseInt(name.substring(name.lastIndexOf(' ') + 1));
            float[] boxes = MeshBVH.triangleBoxes(mesh);
            FlatBVH tree = name.startsWith("median") ? new MedianSplitBuilder(leaf).build(boxes) : new SahBuilder(leaf).build(boxes);
            Counting counting = new Counting(new MeshBVH(mesh, tree, List.of()));
            double[] primary = rays.get(0);
            double[] shadow = rays.get(1);
            Ray ray = new Ray();
            long[] box = new long[2];
            long[] tri = new long[2];
            for (int k = 0; k < primary.length; k += 6) {
                ray.set(primary[k], primary[k + 1], primary[k + 2], primary[k + 3], primary[k + 4], primary[k + 5]);
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                sr.scratch.shearedRay.load(ray);
                long before = sr.boxTests;
                counting.tests = 0;
                counting.bvh.bvh().closestHit(ray, sr, counting);
                box[0] += sr.boxTests - before;
                tri[0] += counting.tests;
            }
            for (int k = 0; k < shadow.length; k += 7) {
                ray.set(shadow[k], shadow[k + 1], shadow[k + 2], shadow[k + 3], shadow[k + 4], shadow[k + 5]);
                sr.scratch.shearedRay.load(ray);
                long before = sr.boxTests;
                counting.tests = 0;
                counting.bvh.bvh().anyHit(ray, shadow[k + 6], sr, counting);
                box[1] += sr.boxTests - before;
                tri[1] += counting.tests;
            }
            long p = primary.length / 6;
            long s = shadow.length / 7;
            System.out.printf(Locale.ROOT, "%-10s %d nodes; per ray: box %.2f, triangle %.2f (primary: %.2f, %.2f; shadow: %.2f, %.2f)%n",
                              name, tree.nodeCount(), (box[0] + box[1]) / (double) (p + s), (tri[0] + tri[1]) / (double) (p + s),
                              box[0] / (double) p, tri[0] / (double) p, box[1] / (double) s, tri[1] / (double) s);
        }
    }

    /** A leaf's triangles tested one at a time, counted; the shadow search stops at the first blocker. */
    private static final class Counting implements Leaves {
        final MeshBVH bvh;
        long tests;

        Counting(MeshBVH bvh) {
            this.bvh = bvh;
        }

        @Override
        public boolean hit(int first, int count, Ray ray, ShadeRec sr) {
            tests += count;
            return bvh.hit(first, count, ray, sr);
        }

        @Override
        public boolean shadowHit(int first, int count, Ray ray, double tMax, ShadeRec sr) {
            for (int tri = first; tri < first + count; tri++) {
                tests++;
                if (bvh.shadowHit(tri, 1, ray, tMax, sr)) {
                    return true;
                }
            }
            return false;
        }
    }

    /**
     * Every third pixel's primary ray in x and y (6 doubles each; the frame's rays, thinned as in
     * the study's frame-ray harness) and the shadow rays from its hit (7: the ray and the light's distance).
     */
    private static List<double[]> frameRays(World world) {
        ViewPlane vp = world.viewPlane();
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        MutableVec3 wi = sr.wi;
        Ray ray = new Ray();
        Ray shadowRay = new Ray();
        int pixels = ((vp.hres() + 2) / 3) * ((vp.vres() + 2) / 3);
        double[] primary = new double[6 * pixels];
        double[] shadow = new double[7 * world.lights().length * pixels];
        int p = 0;
        int s = 0;
        for (int y = 0; y < vp.vres(); y += 3) {
            for (int x = 0; x < vp.hres(); x += 3) {
                world.camera().generateRay(vp, x + 0.5, y + 0.5, 0, 0, ray);
                p = store(ray, primary, p);
                sr.depth = 0;
                if (!world.hit(ray, sr)) {
                    continue;
                }
                for (Light light : world.lights()) {
                    double distance = light.sample(sr, 0.5, 0.5, wi);
                    if (sr.normal.dot(wi) <= 0 || sr.geometricNormal.dot(wi) <= 0) {
                        continue;
                    }
                    sr.spawnRay(wi.x, wi.y, wi.z, shadowRay);
                    s = store(shadowRay, shadow, s);
                    shadow[s++] = distance;
                }
            }
        }
        return List.of(java.util.Arrays.copyOf(primary, p), java.util.Arrays.copyOf(shadow, s));
    }

    private static int store(Ray r, double[] to, int at) {
        to[at] = r.ox;
        to[at + 1] = r.oy;
        to[at + 2] = r.oz;
        to[at + 3] = r.dx;
        to[at + 4] = r.dy;
        to[at + 5] = r.dz;
        return at + 6;
    }
}

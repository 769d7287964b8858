package raytracer.accel;

import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.io.obj.ObjLoader;
import raytracer.lights.Ambient;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.shapes.mesh.Mesh;

/**
 * BVH traversal on the Stanford bunny and dragon (from the repository's assets/, or -Draytracer.assets=DIR):
 * closest hit for camera rays through the mesh's bounding box, and any hit for shadow rays from
 * points on the surface towards a light, for both builders. Each operation sets its ray from
 * stored numbers, as the renderer does, so what a search derives from its ray is timed with it.
 * Reports rays per microsecond, one thread.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgs = "-Xmx1g")
public class MeshTraversalBenchmark {
    @Param({"stanford-bunny.obj.gz", "stanford-dragon.obj.gz"})
    public String mesh;

    @Param({"median", "sah"})
    public String builder;

    private static final int RAYS = 4096;
    /** Per ray: origin and direction (and for shadow rays the distance to the light). */
    private final double[] cameraRays = new double[6 * RAYS];
    private final double[] shadowRays = new double[7 * RAYS];
    private final Ray ray = new Ray();
    private MeshBVH bvh;
    private ShadeRec sr;
    private int next;

    @Setup
    public void setUp() throws Exception {
        String assets = System.getProperty("raytracer.assets", "assets");
        Mesh m = ObjLoader.load(Path.of(assets, "meshes", mesh), false).mesh();
        FlatBVH tree = builder.equals("sah") ? new SahBuilder(4).build(MeshBVH.triangleBounds(m))
                                             : new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(m));
        bvh = new MeshBVH(m, tree, List.of());
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        sr = new WorkerScratch(world).shadeRec(0);
        BBox box = m.bounds();
        Point3D c = box.center();
        double size = Math.max(box.x1() - box.x0(), box.y1() - box.y0());
        Point3D eye = new Point3D(c.x(), c.y() + 0.2 * size, c.z() + 1.5 * size);
        Point3D light = new Point3D(c.x() - size, c.y() + 2 * size, c.z() + size);
        SplittableRandom r = new SplittableRandom(1);
        Ray shadow = new Ray();
        int made = 0;
        while (made < RAYS) {
            double tx = r.nextDouble(box.x0(), box.x1());
            double ty = r.nextDouble(box.y0(), box.y1());
            ray.set(eye.x(), eye.y(), eye.z(), tx - eye.x(), ty - eye.y(), c.z() - eye.z());
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            if (!bvh.hit(ray, sr)) {
                continue;
            }
            sr.complete(ray);
            store(ray, cameraRays, 6 * made);
            double dx = light.x() - sr.hitPoint.x;
            double dy = light.y() - sr.hitPoint.y;
            double dz = light.z() - sr.hitPoint.z;
            double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
            store(sr.spawnRay(dx / length, dy / length, dz / length, shadow), shadowRays, 7 * made);
            shadowRays[7 * made + 6] = length;
            made++;
        }
    }

    private static void store(Ray r, double[] to, int at) {
        to[at] = r.ox;
        to[at + 1] = r.oy;
        to[at + 2] = r.oz;
        to[at + 3] = r.dx;
        to[at + 4] = r.dy;
        to[at + 5] = r.dz;
    }

    @Benchmark
    public boolean closestHit() {
        int k = 6 * (next++ & (RAYS - 1));
        ray.set(cameraRays[k], cameraRays[k + 1], cameraRays[k + 2], cameraRays[k + 3], cameraRays[k + 4], cameraRays[k + 5]);
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        return bvh.hit(ray, sr);
    }

    @Benchmark
    public boolean anyHit() {
        int k = 7 * (next++ & (RAYS - 1));
        ray.set(shadowRays[k], shadowRays[k + 1], shadowRays[k + 2], shadowRays[k + 3], shadowRays[k + 4], shadowRays[k + 5]);
        return bvh.shadowHit(ray, shadowRays[k + 6], sr);
    }
}

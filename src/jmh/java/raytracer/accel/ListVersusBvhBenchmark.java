package raytracer.accel;

import java.util.ArrayList;
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
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.shapes.Sphere;

/**
 * Closest hits among N spheres scattered in a box, searched as a list or through a median-split BVH.
 * The crossing point sets {@link Aggregation#AUTO_THRESHOLD}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class ListVersusBvhBenchmark {
    @Param({"2", "4", "8", "16", "32"})
    public int count;

    private static final int RAYS = 1024;
    private final Ray[] rays = new Ray[RAYS];
    private GeometricObject[] list;
    private GeometricObject bvh;
    private ShadeRec sr;
    private int next;

    @Setup
    public void setUp() {
        SplittableRandom r = new SplittableRandom(1);
        List<GeometricObject> spheres = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            spheres.add(new Sphere(new Point3D(r.nextDouble(-4, 4), r.nextDouble(0, 3), r.nextDouble(-4, 4)), 0.5));
        }
        list = spheres.toArray(new GeometricObject[0]);
        bvh = ObjectBVH.build(spheres, false);
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 2, 10), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        sr = new WorkerScratch(world).shadeRec(0);
        for (int i = 0; i < RAYS; i++) {
            rays[i] = new Ray().set(0, 2, 10, r.nextDouble(-4, 4), r.nextDouble(-2, 1), -10);
        }
    }

    @Benchmark
    public boolean list() {
        Ray ray = rays[next++ & (RAYS - 1)];
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        boolean hit = false;
        for (GeometricObject o : list) {
            hit |= o.hit(ray, sr);
        }
        return hit;
    }

    @Benchmark
    public boolean bvh() {
        Ray ray = rays[next++ & (RAYS - 1)];
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        return bvh.hit(ray, sr);
    }
}

package raytracer.render;

import java.nio.file.Path;
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
import raytracer.accel.Aggregation;
import raytracer.accel.MeshBVH;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.io.scene.SceneLoader;
import raytracer.math.Ray;
import raytracer.math.MutableVec3;

/**
 * The rays of a benchmark frame (scenes/bench-*.yaml, 1 sample per pixel, two point lights),
 * replayed one per operation in the renderer's tile order on one thread: the closest-hit search of
 * each primary ray (with the winner's completion) and the any-hit search of each shadow ray,
 * without shading: where the frame's time goes (docs/performance.md, "JMH benchmarks"; figures of
 * 23 November 2026 in its history); the set-up prints how many box tests each kind of ray makes.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgs = "-Xmx2g")
public class FrameRaysBenchmark {
    @Param({"bench-dragon", "bench-bunny"})
    public String scene;

    private World world;
    private ShadeRec sr;
    private final Ray ray = new Ray();
    private double[] primary;
    private double[] shadow;
    private int primaryCount;
    private int shadowCount;
    private int nextPrimary;
    private int nextShadow;

    @Setup
    public void setUp() throws Exception {
        world = SceneLoader.load(Path.of("scenes", scene + ".yaml")).world();
        world.prepare(objects -> Aggregation.organize(objects, Aggregation.Mode.AUTO));
        ViewPlane vp = world.viewPlane();
        int width = vp.hres();
        int height = vp.vres();
        sr = new WorkerScratch(world).shadeRec(0);
        primary = new double[6 * width * height];
        shadow = new double[7 * 2 * width * height];
        Ray shadowRay = new Ray();
        MutableVec3 wi = sr.wi;
        // box tests by kind of ray: primary to the mesh or elsewhere, shadow from the mesh or elsewhere
        long[] rays = new long[4];
        long[] tests = new long[4];
        for (int ty = 0; ty < height; ty += Renderer.TILE_SIZE) {
            for (int tx = 0; tx < width; tx += Renderer.TILE_SIZE) {
                for (int y = ty; y < Math.min(height, ty + Renderer.TILE_SIZE); y++) {
                    for (int x = tx; x < Math.min(width, tx + Renderer.TILE_SIZE); x++) {
                        world.camera().generateRay(vp, x + 0.5, y + 0.5, 0, 0, ray);
                        store(ray, primary, 6 * primaryCount++);
                        sr.depth = 0;
                        long before = sr.boxTests;
                        boolean hit = world.hit(ray, sr);
                        int kind = hit && sr.object instanceof MeshBVH ? 0 : 1;
                        rays[kind]++;
                        tests[kind] += sr.boxTests - before;
                        if (!hit) {
                            continue;
                        }
                        // the shadow rays DirectLighting would trace from this hit
                        for (Light light : world.lights()) {
                            double distance = light.sample(sr, 0.5, 0.5, wi);
                            if (sr.normal.dot(wi) <= 0 || sr.geometricNormal.dot(wi) <= 0) {
                                continue;
                            }
                            sr.spawnRay(wi.x, wi.y, wi.z, shadowRay);
                            long start = sr.boxTests;
                            world.shadowHit(shadowRay, distance, sr);
                            rays[kind + 2]++;
                            tests[kind + 2] += sr.boxTests - start;
                            store(shadowRay, shadow, 7 * shadowCount);
                            shadow[7 * shadowCount++ + 6] = distance;
                        }
                    }
                }
            }
        }
        String[] names = {"primary rays to the mesh", "other primary rays", "shadow rays from the mesh", "other shadow rays"};
        for (int k = 0; k < 4; k++) {
            System.out.printf("# %s: %d, %.1f box tests each%n", names[k], rays[k], tests[k] / Math.max(1.0, rays[k]));
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
    public boolean primaryRay() {
        int k = 6 * nextPrimary;
        nextPrimary = nextPrimary + 1 == primaryCount ? 0 : nextPrimary + 1;
        ray.set(primary[k], primary[k + 1], primary[k + 2], primary[k + 3], primary[k + 4], primary[k + 5]);
        sr.depth = 0;
        return world.hit(ray, sr);
    }

    @Benchmark
    public boolean shadowRay() {
        int k = 7 * nextShadow;
        nextShadow = nextShadow + 1 == shadowCount ? 0 : nextShadow + 1;
        ray.set(shadow[k], shadow[k + 1], shadow[k + 2], shadow[k + 3], shadow[k + 4], shadow[k + 5]);
        return world.shadowHit(ray, shadow[k + 6], sr);
    }
}

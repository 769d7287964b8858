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
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneLoader;
import raytracer.samplers.Samplers;

/**
 * One pixel of scenes/arealight-spheres.yaml per operation (16 samples, one area-light sample
 * each, four objects), on one thread: the simple-scene path of issue 13 (camera ray, closest hit
 * over a short list, light sample, shadow ray, shading). Operations per microsecond times 16 is
 * samples per microsecond; {@code -prof gc} shows the path allocates nothing.
 * {@code gradle jmh -Pjmh='AreaLightSampleBenchmark -prof gc'} from the project folder.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class AreaLightSampleBenchmark {
    @Param({"multi-jittered", "sobol"})
    public String sampler;

    private Workers workers;
    private Renderer renderer;
    private WorkerScratch scratch;
    private Film film;
    private int width;
    private int height;
    private int next;

    @Setup
    public void setUp() throws Exception {
        LoadedScene loaded = SceneLoader.load(Path.of("scenes/arealight-spheres.yaml"));
        World world = loaded.world();
        world.setViewPlane(world.viewPlane().withSampler(Samplers.byName(sampler)));
        world.prepare();
        workers = new Workers(1); // renderPixel runs on the benchmark's thread; the pool stays idle
        renderer = new Renderer(world, loaded.rayTree(), workers, 1);
        scratch = new WorkerScratch(world, loaded.rayTree());
        width = world.viewPlane().hres();
        height = world.viewPlane().vres();
        film = new Film(width, height);
    }

    @TearDown
    public void tearDown() {
        workers.close();
    }

    @Benchmark
    public void pixel() {
        // a fixed pseudo-random walk over the image, so that floor, spheres, shadows and sky all count
        next = (next + 7919) % (width * height);
        renderer.renderPixel(next % width, next / width, scratch, film);
    }
}

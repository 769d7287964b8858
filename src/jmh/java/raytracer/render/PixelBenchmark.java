package raytracer.render;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
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
 * One pixel per operation (16 samples), on one thread. {@code scene=default}: the default scene
 * (mirror recursion, two lights with shadows); {@code scene=arealight-spheres}: the simple-scene
 * path of the convergence study (four objects, one area-light sample per pixel sample), where operations per
 * millisecond times 16 is samples per millisecond. {@code sampler} overrides the scene's pattern
 * ({@code -p sampler=sobol}). With {@code -prof gc} it shows that the whole per-ray path, camera to
 * shading, allocates nothing. Run from the project folder (the area-light scene is read from
 * {@code scenes/}).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class PixelBenchmark {
    @Param({"default", "arealight-spheres"})
    public String scene;

    /** A sampler's name, or "scene" for the scene's own. */
    @Param({"scene"})
    public String sampler;

    private Workers workers;
    private Renderer renderer;
    private WorkerScratch scratch;
    private PixelSink pixels;
    private int width;
    private int height;
    private int next;

    @Setup
    public void setUp() throws Exception {
        LoadedScene loaded = scene.equals("default") ? SceneLoader.load("default scene", defaultScene())
                             : SceneLoader.load(Path.of("scenes", scene + ".yaml"));
        World world = loaded.world();
        if (!sampler.equals("scene")) {
            world.setViewPlane(world.viewPlane().withSampler(Samplers.byName(sampler)));
        }
        world.prepare();
        workers = new Workers(1); // renderPixel runs on the benchmark's thread; the pool stays idle
        renderer = new Renderer(world, loaded.rayTree(), workers, 1);
        scratch = new WorkerScratch(world, loaded.rayTree());
        width = world.viewPlane().hres();
        height = world.viewPlane().vres();
        pixels = new BoxAverage(new Film(width, height));
    }

    @TearDown
    public void tearDown() {
        workers.close();
    }

    private static String defaultScene() throws IOException {
        try (InputStream in = PixelBenchmark.class.getResourceAsStream("/raytracer/scenes/default.yaml")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Benchmark
    public void pixel() {
        // walk the image in a fixed pseudo-random order so that all parts of the scene are measured
        next = (next + 7919) % (width * height);
        renderer.renderPixel(next % width, next / width, scratch, pixels);
    }
}

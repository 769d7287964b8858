package raytracer.render;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
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

/**
 * One pixel of the default scene per operation (16 samples, mirror recursion, two lights with
 * shadows), on one thread. With {@code -prof gc} it shows that the whole per-ray path, camera to
 * shading, allocates nothing.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class PixelBenchmark {
    private Workers workers;
    private Renderer renderer;
    private WorkerScratch scratch;
    private Film film;
    private int width;
    private int height;
    private int next;

    @Setup
    public void setUp() throws Exception {
        LoadedScene loaded = SceneLoader.load("default scene", defaultScene());
        World world = loaded.world();
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

    private static String defaultScene() throws IOException {
        try (InputStream in = PixelBenchmark.class.getResourceAsStream("/raytracer/scenes/default.yaml")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Benchmark
    public void pixel() {
        // walk the image in a fixed pseudo-random order so that all parts of the scene are measured
        next = (next + 7919) % (width * height);
        renderer.renderPixel(next % width, next / width, scratch, film);
    }
}

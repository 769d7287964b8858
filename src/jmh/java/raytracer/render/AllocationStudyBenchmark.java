package raytracer.render;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Threads;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.ThreadParams;
import raytracer.accel.Aggregation;
import raytracer.core.RayTreeSettings;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneLoader;
import raytracer.study.AllocationMode;

/**
 * The allocation study (docs/performance.md, "The allocation study"): the same rays through the
 * same arithmetic with the renderer's reused hit records and mutable vectors ({@code reuse}), a new
 * hit record per ray ({@code fresh}) and new records plus immutable vectors and colours from the
 * completed hit on ({@code immutable}); {@code AllocationModeTest} checks that the images are equal
 * to the bit. Two workloads, each on 1 and 2 threads:
 * <ul>
 * <li>{@code pixel}, {@code pixelTwoThreads}: one pixel of the default scene per operation (16
 *     samples, mirror recursion, two lights with shadows), on 1 or 2 JMH threads, each with its own
 *     worker scratch and walk through the image;</li>
 * <li>{@code frame}: the dragon bench scene at 480x270 (1 sample, two point lights with shadows),
 *     a whole frame per operation, rendered by the renderer on a pool of {@code threads} workers.</li>
 * </ul>
 * Scenes are loaded and prepared once per fork, untimed. Run with {@code -prof gc} for B/op,
 * allocation rate and GC count and time; {@code -jvm} and {@code -jvmArgsAppend -XX:+UseParallelGC}
 * pick the JVM and collector. Passing {@code -t} overrides the pixel methods' thread counts.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 5, time = 2)
// the heap's limit as in the other benchmarks; its start and growth are the collector's own
@Fork(value = 2, jvmArgs = "-Xmx2g")
public class AllocationStudyBenchmark {
    @Param({"reuse", "fresh", "immutable"})
    public String mode;

    static final int FRAME_WIDTH = 480;
    static final int FRAME_HEIGHT = 270;

    /** The default scene as the renderer prepares it, in the benchmark's mode. */
    @State(Scope.Benchmark)
    public static class DefaultScene {
        AllocationMode allocation;
        World world;
        RayTreeSettings rayTree;
        Workers workers;
        Renderer renderer;

        @Setup(Level.Trial)
        public void load(AllocationStudyBenchmark study) throws Exception {
            allocation = AllocationMode.parse(study.mode);
            String text;
            try (InputStream in = AllocationStudyBenchmark.class.getResourceAsStream("/raytracer/scenes/default.yaml")) {
                text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
            LoadedScene loaded = SceneLoader.load("default scene", text);
            world = loaded.world();
            rayTree = loaded.rayTree();
            world.prepare(objects -> Aggregation.organize(objects, Aggregation.Mode.AUTO));
            allocation.install(world, rayTree);
            workers = new Workers(1); // renderPixel runs on the benchmark's threads; the pool stays idle
            renderer = allocation.renderer(world, rayTree, workers, 1);
        }

        @TearDown(Level.Trial)
        public void close() {
            workers.close();
        }
    }

    /** One benchmark thread's worker scratch, image and place in its walk through the image. */
    @State(Scope.Thread)
    public static class PixelWalk {
        DefaultScene scene;
        WorkerScratch scratch;
        PixelSink sink;
        int width;
        int pixels;
        int next;

        @Setup(Level.Trial)
        public void start(DefaultScene scene, ThreadParams thread) {
            this.scene = scene;
            scratch = scene.allocation.scratch(scene.world, scene.rayTree);
            width = scene.world.viewPlane().hres();
            pixels = width * scene.world.viewPlane().vres();
            sink = new BoxAverage(new Film(width, scene.world.viewPlane().vres()));
            next = (int) ((long) pixels * thread.getThreadIndex() / thread.getThreadCount());
        }

        void renderNext() {
            // a fixed pseudo-random walk, so that every part of the scene is measured
            next = (next + 7919) % pixels;
            scene.renderer.renderPixel(next % width, next / width, scratch, sink);
        }
    }

    /** The dragon bench scene at 480x270, rendered whole on a pool of {@code threads} workers. */
    @State(Scope.Benchmark)
    public static class DragonFrame {
        @Param({"1", "2"})
        public int threads;

        Workers workers;
        Renderer renderer;
        Film film;

        @Setup(Level.Trial)
        public void load(AllocationStudyBenchmark study) throws Exception {
            AllocationMode allocation = AllocationMode.parse(study.mode);
            LoadedScene loaded = SceneLoader.load(Path.of("scenes", "bench-dragon.yaml"));
            World world = loaded.world();
            world.setViewPlane(world.viewPlane().withResolution(FRAME_WIDTH, FRAME_HEIGHT));
            world.prepare(objects -> Aggregation.organize(objects, Aggregation.Mode.AUTO));
            allocation.install(world, loaded.rayTree());
            workers = new Workers(threads);
            renderer = allocation.renderer(world, loaded.rayTree(), workers, 1);
            film = new Film(FRAME_WIDTH, FRAME_HEIGHT);
        }

        @TearDown(Level.Trial)
        public void close() {
            workers.close();
        }
    }

    @Benchmark
    @Threads(1)
    @OutputTimeUnit(TimeUnit.MILLISECONDS)
    public void pixel(PixelWalk walk) {
        walk.renderNext();
    }

    @Benchmark
    @Threads(2)
    @OutputTimeUnit(TimeUnit.MILLISECONDS)
    public void pixelTwoThreads(PixelWalk walk) {
        walk.renderNext();
    }

    @Benchmark
    @OutputTimeUnit(TimeUnit.SECONDS)
    public RenderStats frame(DragonFrame frame) {
        return frame.renderer.render(frame.film);
    }
}

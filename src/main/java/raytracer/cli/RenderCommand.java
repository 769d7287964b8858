package raytracer.cli;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raytracer.accel.Aggregation;
import raytracer.accel.ObjectBVH;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.DisplayEncoding;
import raytracer.image.FalseColor;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.LoadReport;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;
import raytracer.render.RenderStats;
import raytracer.render.Renderer;
import raytracer.render.Workers;
import raytracer.tracers.BvhCost;

/**
 * {@code render [SCENE] -o FILE ...}: loads a scene file (or the embedded default scene), applies the
 * command-line overrides, renders, and writes the image atomically. Every failure is one line on
 * stderr and a non-zero exit; {@code --verbose} adds the stack trace.
 */
@Command(name = "render", mixinStandardHelpOptions = true, versionProvider = RenderCommand.Version.class,
         sortOptions = false,
         description = "Renders a scene file (YAML or JSON) to PNG or PFM. Without SCENE, renders the built-in default scene.")
public final class RenderCommand implements Callable<Integer> {
    static final String DEFAULT_SCENE_RESOURCE = "/raytracer/scenes/default.yaml";

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE", description = "Scene file (.yaml, .yml or .json).")
    Path scene;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE",
            description = "Output image, .png (sRGB 8-bit) or .pfm (linear float). Default: <scene name>.png")
    Path output;

    @Option(names = {"-W", "--width"}, paramLabel = "W", description = "Image width in pixels (overrides the scene).")
    Integer width;

    @Option(names = {"-H", "--height"}, paramLabel = "H", description = "Image height in pixels (overrides the scene).")
    Integer height;

    @Option(names = {"-s", "--spp"}, paramLabel = "N", description = "Samples per pixel (overrides the scene).")
    Integer samples;

    @Option(names = {"-t", "--threads"}, paramLabel = "T", description = "Worker threads, 1 to " + Workers.MAX_THREADS + ". Default: all cores (${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = "--seed", paramLabel = "S", description = "Random seed; the same seed gives the same image. Default: ${DEFAULT-VALUE}.")
    long seed = 1;

    @Option(names = {"-d", "--max-depth"}, paramLabel = "D", description = "Deepest recursion for mirror rays, 0 to " + ViewPlane.MAX_DEPTH + " (overrides the scene).")
    Integer maxDepth;

    @Option(names = "--cutoff", paramLabel = "C",
            description = "Adaptive ray-tree cutoff (overrides the scene): branches weighing less than C and light "
                          + "samples adding less than C are not traced; 0 traces the whole tree.")
    Double cutoff;

    @Option(names = "--encoding", paramLabel = "E",
            description = "PNG encoding (overrides the scene): srgb, or linear (clamped radiance as the code value, as the report did).")
    String encoding;

    @Option(names = "--view", paramLabel = "VIEW",
            description = "What to show: shaded (default) or bvh-cost (false colour: brighter = more bounding-volume tests).")
    String view = "shaded";

    @Option(names = "--pass", paramLabel = "PASS",
            description = "Terms of the first hit (report figures 4 and 6): full, direct, reflection, refraction, "
                          + "magenta-reflection or no-fresnel. Default: the scene's, else full.")
    String pass;

    @Option(names = "--accel", paramLabel = "MODE",
            description = "Search structure for the scene's objects: auto (default; a BVH from "
                          + Aggregation.AUTO_THRESHOLD + " bounded objects on), list, median or sah.")
    String accel = "auto";

    @Option(names = "--repeat", paramLabel = "N",
            description = "Render N times in this JVM and report each (benchmarking: the first render includes JIT warm-up).")
    int repeat = 1;

    @Option(names = "--stats", description = "Print a breakdown: load steps, render time, rays by kind, BVH tests per ray, peak heap.")
    boolean stats;

    @Option(names = {"-q", "--quiet"}, description = "No progress bar and no summary line.")
    boolean quiet;

    @Option(names = {"-v", "--verbose"}, description = "Print stack traces with errors.")
    boolean verbose;

    @Spec
    CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(new PrintWriter(System.err, true), args));
    }

    /**
     * Runs the command, writing messages to {@code err}, and returns its exit code: 0 done, 1 bad
     * input or failed render, 2 bad usage.
     */
    public static int run(PrintWriter err, String... args) {
        CommandLine cli = new CommandLine(new RenderCommand());
        cli.setErr(err);
        cli.setParameterExceptionHandler((ex, a) -> {
            ex.getCommandLine().getErr().println("render: error: " + ex.getMessage() + " (see render --help)");
            return 2;
        });
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            RenderCommand command = commandLine.getCommand();
            commandLine.getErr().println("render: error: " + oneLine(ex));
            if (command.verbose) {
                ex.printStackTrace(commandLine.getErr());
            }
            return 1;
        });
        return cli.execute(args);
    }

    @Override
    public Integer call() throws Exception {
        try {
            return render();
        } catch (StackOverflowError e) {
            throw new IllegalStateException("the recursion went deeper than a worker thread's stack holds; lower the "
                                            + "scene's max-depth or --max-depth", e);
        } catch (OutOfMemoryError e) {
            // the film and the scene are unreachable now, so there is memory to say so
            throw new IllegalStateException("out of memory for this scene and image size; give Java more heap, e.g. "
                                            + "java -Xmx8g -jar render.jar ... (now at most "
                                            + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB)", e);
        }
    }

    private int render() throws Exception {
        validateOptions();
        Path out = output != null ? output : Path.of(defaultOutputName());
        String unwritable = whyUnwritable(out);
        if (unwritable != null) {
            // a bad -o is a bad option value (exit code 2), found before rendering, not after
            throw new CommandLine.ParameterException(spec.commandLine(), "cannot write " + out + ": " + unwritable);
        }
        Aggregation.Mode accelMode = usage(() -> Aggregation.Mode.parse(accel));
        boolean costView = usage(this::parseView);
        ShadingPass shadingPass = pass == null ? null : usage(() -> ShadingPass.parse(pass));
        DisplayEncoding displayEncoding = encoding == null ? null : usage(this::parseEncoding);
        try (Workers workers = new Workers(threads)) {
            return render(workers, out, accelMode, costView, shadingPass, displayEncoding);
        }
    }

    private int render(Workers workers, Path out, Aggregation.Mode accelMode, boolean costView, ShadingPass shadingPass,
                       DisplayEncoding displayEncoding) throws Exception {
        long loadStart = System.nanoTime();
        LoadedScene loaded = workers.call(this::loadScene);
        long loadNanos = System.nanoTime() - loadStart;
        if (!quiet) {
            loaded.report().warnings().forEach(w -> spec.commandLine().getErr().println("render: warning: " + w));
        }
        World world = loaded.world();
        applyOverrides(world);
        RayTreeSettings rayTree = loaded.rayTree();
        if (shadingPass != null) {
            rayTree = rayTree.withPass(shadingPass);
        }
        if (cutoff != null) {
            rayTree = rayTree.withCutoff(cutoff);
        }
        DisplayEncoding display = displayEncoding != null ? displayEncoding : loaded.encoding();
        long prepareStart = System.nanoTime();
        workers.call(() -> {
            world.prepare(objects -> Aggregation.organize(objects, accelMode));
            return null;
        });
        long prepareNanos = System.nanoTime() - prepareStart;
        if (costView) {
            world.setTracer(BvhCost::new);
        }

        ViewPlane vp = world.viewPlane();
        PrintWriter err = spec.commandLine().getErr();
        for (int i = 1; i < repeat; i++) {
            RenderStats warmup = new Renderer(world, rayTree, workers, seed).render(new Film(vp.hres(), vp.vres()));
            printRepeat(err, i, warmup);
        }
        Renderer renderer = new Renderer(world, rayTree, workers, seed);
        Film film = new Film(vp.hres(), vp.vres());
        RenderStats stats;
        if (!quiet && System.console() != null) {
            Progress progress = new Progress(System.err, renderer::progress);
            try {
                stats = renderer.render(film);
            } finally {
                progress.close();
            }
        } else {
            stats = renderer.render(film);
        }
        if (repeat > 1) {
            printRepeat(err, repeat, stats);
        }
        if (costView) {
            // the film holds each pixel's mean over its samples
            double[] range = FalseColor.range(film);
            film = FalseColor.apply(film, range[0], range[1]);
            // printed even with --quiet: it is the image's legend
            String format = vp.numSamples() == 1 ? "%.0f" : "%.1f";
            err.printf("bvh-cost: " + format + " to " + format + " bounding-volume tests per %s (black to white)%n",
                       range[0], range[1], vp.numSamples() == 1 ? "pixel" : "ray, averaged over each pixel");
        }
        ImageWriters.write(film, costView ? 1 : vp.exposure(), costView || display.srgbCurve(), out);
        if (!quiet) {
            err.println(summary(stats, out));
        }
        if (this.stats) {
            printStats(err, world, loaded.report(), loadNanos, prepareNanos, stats);
        }
        return 0;
    }

    private void printRepeat(PrintWriter err, int i, RenderStats s) {
        err.printf("render %d of %d: %.3f s, %.2f M rays/s%n", i, repeat, s.seconds(), s.raysPerSecond() / 1e6);
    }

    private DisplayEncoding parseEncoding() {
        return DisplayEncoding.named(encoding).orElseThrow(() -> new IllegalArgumentException(
            "unknown --encoding '" + encoding + "'; allowed: " + DisplayEncoding.NAMES));
    }

    /** Runs an option's parser, turning its complaint into a usage error (exit code 2). */
    private <T> T usage(Supplier<T> parse) {
        try {
            return parse.get();
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    private boolean parseView() {
        return switch (view) {
            case "shaded" -> false;
            case "bvh-cost" -> true;
            default -> throw new IllegalArgumentException("unknown view '" + view + "'; allowed: shaded, bvh-cost");
        };
    }

    private static void printStats(PrintWriter err, World world, LoadReport report, long loadNanos, long prepareNanos, RenderStats s) {
        err.printf("stats: load scene %.3f s", loadNanos / 1e9);
        report.timings().forEach((step, nanos) -> err.printf(" (%s %.3f s)", step, nanos / 1e9));
        err.println();
        report.statistics().forEach(line -> err.println("stats: " + line));
        boolean topLevelBvh = world.searched().stream().anyMatch(ObjectBVH.class::isInstance);
        err.printf("stats: prepare (%s) %.3f s, render %.3f s%n", topLevelBvh ? "top-level BVH" : "objects in a list",
                   prepareNanos / 1e9, s.seconds());
        err.printf("stats: rays %d (primary %d, shadow %d, secondary %d), %.2f M rays/s%n",
                   s.totalRays(), s.primaryRays(), s.shadowRays(), s.secondaryRays(), s.raysPerSecond() / 1e6);
        err.printf("stats: %.1f bounding-volume tests (BVH node boxes examined) per ray, peak heap %.0f MiB%n",
                   s.boxTestsPerRay(), peakHeapBytes() / (1024.0 * 1024.0));
    }

    /** The sum of the peak usage of the heap's memory pools since the JVM started. */
    static long peakHeapBytes() {
        long peak = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                peak += pool.getPeakUsage().getUsed();
            }
        }
        return peak;
    }

    /** Option values picocli's types cannot check: a bad one is a usage error (exit code 2). */
    private void validateOptions() {
        requireAtLeast("--width", width, 1);
        requireAtLeast("--height", height, 1);
        requireAtLeast("--spp", samples, 1);
        requireWithin("--max-depth", maxDepth, 0, ViewPlane.MAX_DEPTH);
        requireWithin("--threads", threads, 1, Workers.MAX_THREADS);
        requireAtLeast("--repeat", repeat, 1);
        if (cutoff != null && !(cutoff >= 0 && cutoff < 1)) {
            throw new CommandLine.ParameterException(spec.commandLine(), "--cutoff must be in [0, 1), got " + cutoff);
        }
        if (width != null && height != null && (long) width * height > Film.MAX_PIXELS) {
            throw new CommandLine.ParameterException(spec.commandLine(), "--width x --height is " + (long) width * height
                                                     + " pixels, more than one image holds (" + Film.MAX_PIXELS + ")");
        }
    }

    private void requireWithin(String option, Integer value, int min, int max) {
        if (value != null && (value < min || value > max)) {
            throw new CommandLine.ParameterException(spec.commandLine(),
                                                     option + " must be " + min + " to " + max + ", got " + value);
        }
    }

    private void requireAtLeast(String option, Integer value, int min) {
        if (value != null && value < min) {
            throw new CommandLine.ParameterException(spec.commandLine(), option + " must be at least " + min + ", got " + value);
        }
    }

    private String defaultOutputName() {
        if (scene == null) {
            return "default.png";
        }
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return (dot > 0 ? name.substring(0, dot) : name) + ".png";
    }

    /** Why the image could not be written to {@code out}, or null if it can be. */
    private static String whyUnwritable(Path out) {
        String extensions = String.join(", ", ImageWriters.EXTENSIONS);
        if (Files.isDirectory(out)) {
            return "it is a directory; give a file name ending in one of " + extensions;
        }
        if (!ImageWriters.isSupported(out)) {
            return "unsupported extension (use one of " + extensions + ")";
        }
        Path dir = out.toAbsolutePath().getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            return "directory " + dir + " does not exist";
        }
        if (!Files.isWritable(dir)) {
            return "directory " + dir + " is not writable";
        }
        if (Files.exists(out) && !Files.isWritable(out)) {
            return "it is read-only";
        }
        return null;
    }

    private LoadedScene loadScene() throws SceneException, IOException {
        if (scene != null) {
            return SceneLoader.load(scene);
        }
        try (InputStream in = RenderCommand.class.getResourceAsStream(DEFAULT_SCENE_RESOURCE)) {
            if (in == null) {
                throw new IOException("the embedded default scene is missing from the jar");
            }
            return SceneLoader.load("default scene", new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }

    private void applyOverrides(World world) {
        ViewPlane vp = world.viewPlane();
        if (width != null || height != null) {
            vp = vp.withResolution(width != null ? width : vp.hres(), height != null ? height : vp.vres());
        }
        if (samples != null) {
            vp = vp.withSamples(samples);
        }
        if (maxDepth != null) {
            vp = vp.withMaxDepth(maxDepth);
        }
        world.setViewPlane(vp);
    }

    static String summary(RenderStats s, Path out) {
        return String.format("%s: %dx%d, %d spp, %d thread%s, %.2f s, %.2f M rays/s (%d primary, %d shadow, %d secondary)%s",
            out, s.width(), s.height(), s.samplesPerPixel(), s.threads(), s.threads() == 1 ? "" : "s",
            s.seconds(), s.raysPerSecond() / 1e6, s.primaryRays(), s.shadowRays(), s.secondaryRays(),
            s.nonFiniteSamples() > 0 ? ", WARNING: " + s.nonFiniteSamples() + " non-finite samples dropped" : "");
    }

    private static String oneLine(Throwable ex) {
        String message = ex.getMessage();
        if (message == null || message.isBlank()) {
            message = ex.getClass().getSimpleName();
        }
        return message.replace('\n', ' ');
    }

    /** Reads the version from the jar manifest. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = RenderCommand.class.getPackage().getImplementationVersion();
            return new String[] {"render " + (v != null ? v : "(development build)")
                                 + " on Java " + System.getProperty("java.version")};
        }
    }
}

package raytracer.spark;

import java.io.PrintWriter;
import java.net.URL;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import java.util.jar.JarFile;
import org.apache.hadoop.conf.Configuration;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raytracer.api.FrameFiles;
import raytracer.api.FrameRange;
import raytracer.api.ImageSettings;
import raytracer.api.Scene;
import raytracer.api.SceneOptions;
import raytracer.cli.ImageOptions;
import raytracer.cli.RenderOptions;
import raytracer.cli.Terminal;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneFile;
import raytracer.render.Renderer;
import raytracer.render.TileImage;
import raytracer.render.TilePixels;

/**
 * {@code spark-submit --class raytracer.spark.SparkRender --jars render.jar render-spark.jar SCENE
 * [--frames A-B | --tasks N] -o OUT}: a scene rendered on Apache Spark, byte for byte the file
 * {@code render} writes. An animation is a task per frame, each frame written by its task; a
 * still (or an animation of fewer frames than the cluster has cores) is runs of its tile list,
 * spread over the image, rendered into arrays and put together on the driver, which writes the
 * file. Files are written atomically under fixed names on any Hadoop file system, so a retried or
 * speculative task is harmless. The options that change the image are render's, checked as render
 * checks them ({@link RenderOptions}, {@link ImageOptions}: the only classes of the command line
 * the job takes, with {@link Terminal}'s escaping), worded for the job by {@link SparkHelp}; this
 * command adds its own. docs/distributed.md tells the whole of it.
 */
@Command(name = "render-spark", sortOptions = false, resourceBundle = "raytracer.spark.SparkHelp",
         description = "Renders a scene file on Apache Spark (run by spark-submit), the same bytes as render. A still is runs of "
                       + "its tiles put together on the driver; an animation (--frames) a task per frame, each written by its task.")
public final class SparkRender implements Callable<Integer> {
    static final int BAD_INPUT = 1;
    static final int BAD_USAGE = 2;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE", description = "Scene file (.yaml, .yml or .json); default: the built-in scene.")
    Path scene;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "Output image, .png or .pfm, a path or any Hadoop file system URI (file:, hdfs:, s3a:); with --frames a "
                          + "pattern with %%d or %%04d for the frame number. Default: <scene name>.png, or <scene name>-%%04d.png.")
    String output;

    @Option(names = "--frames", paramLabel = "A-B", description = "Render frames A to B (or one frame, A) of the scene's animation.")
    String frames;

    @Option(names = "--tasks", paramLabel = "N",
            description = "Tasks in all: runs of the tile list for a still, or frames split into runs when N is more than the "
                          + "frames. Default: a task per frame, or three per core for a still.")
    Integer tasks;

    @Option(names = "--scene-on-executors", paramLabel = "PATH",
            description = "The scene file's path on the executors, whose folder holds its meshes and images there (where "
                          + "--archives unpacks them). Default: the scene's absolute path here (a shared file system).")
    String sceneOnExecutors;

    @Mixin
    ImageOptions image = new ImageOptions();

    @Mixin
    RenderOptions options = new RenderOptions();

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help message and exit.")
    boolean help;

    @Spec
    CommandSpec spec;

    /** The context to run in (a test's); null: one made from spark-submit's configuration and stopped at the end. */
    private final JavaSparkContext given;
    private final PrintWriter err;

    private SparkRender(JavaSparkContext given, PrintWriter err) {
        this.given = given;
        this.err = err;
    }

    /**
     * spark-submit's entry. When the SnakeYAML this JVM finds first is not the one render.jar holds
     * (a pyspark distribution's jars come first on the driver's class path), the command runs
     * again in a loader that finds ours first ({@link OursFirst}), so a scene reads the same.
     */
    public static void main(String[] args) throws Exception {
        URL ours = location(raytracer.io.scene.SceneLoader.class);
        URL yaml = location(org.yaml.snakeyaml.LoaderOptions.class);
        boolean oursHoldsYaml = false;
        if (ours != null && ours.getPath().endsWith(".jar")) {
            // from the URI, not the URL's path: that is percent-encoded (a space in a folder's name)
            try (JarFile jar = new JarFile(Path.of(ours.toURI()).toFile())) {
                oursHoldsYaml = jar.getEntry("org/yaml/snakeyaml/LoaderOptions.class") != null;
            }
        }
        if (oursHoldsYaml && !ours.equals(yaml) && !(SparkRender.class.getClassLoader() instanceof OursFirst)) {
            try (OursFirst loader = new OursFirst(new URL[] {location(SparkRender.class), ours}, SparkRender.class.getClassLoader())) {
                Thread.currentThread().setContextClassLoader(loader);
                Object code = loader.loadClass(SparkRender.class.getName()).getMethod("runMain", String[].class).invoke(null, (Object) args);
                System.exit((Integer) code);
            }
        }
        System.exit(runMain(args));
    }

    private static URL location(Class<?> type) {
        return type.getProtectionDomain().getCodeSource() == null ? null : type.getProtectionDomain().getCodeSource().getLocation();
    }

    /** The command with spark-submit's configuration; returns the exit code. */
    public static int runMain(String[] args) {
        return run(null, new PrintWriter(System.err, true), args);
    }

    /**
     * Runs the command in {@code sc} (null: a context made from spark-submit's configuration),
     * writing messages to {@code err}; returns the exit code: 0 done, 1 bad input or a failed
     * render, 2 bad usage. Every failure is one line starting {@code render-spark: error:}.
     */
    public static int run(JavaSparkContext sc, PrintWriter err, String... args) {
        // every line, the job's own as picocli's, through the escaping render's lines take: a scene's
        // or an output's name echoed cannot drive the terminal
        PrintWriter escaped = new PrintWriter(Terminal.escaping(err), true);
        SparkRender command = new SparkRender(sc, escaped);
        CommandLine cli = new CommandLine(command);
        cli.setErr(escaped);
        cli.setParameterExceptionHandler((ex, a) -> {
            ex.getCommandLine().getErr().println("render-spark: error: " + Terminal.line(ex.getMessage()) + " (see render-spark --help)");
            return BAD_USAGE;
        });
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            commandLine.getErr().println("render-spark: error: " + oneLine(ex));
            if (command.options.verbose()) {
                ex.printStackTrace(commandLine.getErr());
            }
            return BAD_INPUT;
        });
        return cli.execute(args);
    }

    /** The first line of the exception's message (a failed Spark job's message goes on with a stack trace), or its class. */
    static String oneLine(Throwable ex) {
        String message = ex.getMessage();
        if (message == null || message.isBlank()) {
            return ex.getClass().getSimpleName();
        }
        return Terminal.line(message.strip().lines().findFirst().orElse(message));
    }

    @Override
    public Integer call() throws Exception {
        CommandLine commandLine = spec.commandLine();
        SceneOptions sceneOptions = options.sceneOptions(image, false);
        // without -t each task takes its own cores
        int threads = options.threadsGiven() ? options.threads() : 0;
        FrameRange range = null;
        if (frames != null) {
            try {
                range = FrameRange.parse(frames);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(commandLine, e.getMessage());
            }
        }
        if (tasks != null && tasks < 1) {
            throw new ParameterException(commandLine, "--tasks must be at least 1");
        }
        String out = output != null ? output : Outputs.defaultFor(scene, range != null);
        String unwritable = Outputs.whyNotWritable(out, range, scene);
        if (unwritable != null) {
            throw new ParameterException(commandLine, unwritable);
        }
        // the driver reads the text and the image settings only: no mesh is read here
        String text = scene == null ? Scene.defaultSceneText() : SceneFile.readText(scene);
        Scene read = Scene.of(scene, text, sceneOptions.withMeshCache(null));
        ImageSettings settings = read.image();
        if (range != null) {
            String why = range.whyNotIn(settings.frames(), read.file().animated());
            if (why != null) {
                throw new ParameterException(commandLine, "--frames " + range.first() + "-" + range.last() + ": " + why);
            }
        }
        long start = System.nanoTime();
        JavaSparkContext sc = given != null ? given : context();
        long contextNanos = System.nanoTime() - start;
        try {
            return render(sc, text, sceneOptions, threads, settings, range != null ? range : new FrameRange(0, 0), range != null, out,
                          contextNanos);
        } finally {
            if (given == null) {
                sc.stop();
            }
        }
    }

    /** A context from spark-submit's configuration, our classes first on the executors, Spark's log at WARN. */
    private JavaSparkContext context() {
        SparkConf conf = new SparkConf();
        conf.setIfMissing("spark.app.name", "render-spark " + (scene == null ? "default scene" : scene.getFileName()));
        conf.setIfMissing("spark.executor.userClassPathFirst", "true");
        JavaSparkContext sc = new JavaSparkContext(conf);
        if (!options.verbose()) {
            sc.setLogLevel("WARN");
        }
        return sc;
    }

    /** Plans the tasks, runs them, writes what the driver puts together, cleans up, and reports. */
    private int render(JavaSparkContext sc, String text, SceneOptions sceneOptions, int threads, ImageSettings settings, FrameRange range,
                       boolean animation, String out, long contextNanos) throws Exception {
        long start = System.nanoTime();
        Configuration hadoop = sc.hadoopConfiguration();
        int tileCount = Renderer.tiles(settings.width(), settings.height()).size();
        int cores = sc.defaultParallelism();
        int wanted = tasks != null ? tasks : animation && range.count() >= cores ? range.count() : 3 * cores;
        int runs = Math.min(tileCount, Math.max(1, (wanted + range.count() - 1) / range.count()));
        String[] outputs = new String[range.count()];
        for (int f = range.first(); f <= range.last(); f++) {
            outputs[f - range.first()] = Outputs.qualify(animation ? FrameFiles.format(out, f) : out, hadoop);
            Outputs.makeFolder(outputs[f - range.first()], hadoop);
        }
        String scenePath = sceneOnExecutors != null ? sceneOnExecutors : scene == null ? null : scene.toAbsolutePath().toString();
        Job job = new Job(text, scenePath, sceneOptions, options.defaultMeshCache(), threads, sc.sc().applicationId(), range.first(),
                          outputs);
        List<int[]> plan = new ArrayList<>();
        for (int f = range.first(); f <= range.last(); f++) {
            for (int r = 0; r < runs; r++) {
                plan.add(runs == 1 ? new int[] {f, -1, -1} : new int[] {f, (int) ((long) r * tileCount / runs), (int) ((long) (r + 1) * tileCount / runs)});
            }
        }
        Progress progress = new Progress(err, plan.size(), runs == 1 ? "frames" : "tile runs", options.quiet());
        sc.sc().addSparkListener(progress);
        List<byte[]> results;
        try {
            results = sc.parallelize(plan, plan.size()).map(new FrameTask(job)).collect();
        } finally {
            sc.sc().removeSparkListener(progress);
            // what killed or failed attempts left behind
            Outputs.removePartials(List.of(outputs), job.runId, hadoop);
        }
        long jobNanos = System.nanoTime() - start;
        Map<Integer, List<TilePixels>> tiles = new TreeMap<>();
        Map<Integer, String> written = new TreeMap<>();
        Map<Integer, Long> sizes = new TreeMap<>();
        JobReport report = new JobReport();
        for (byte[] bytes : results) {
            TaskResult r = TaskResult.decode(bytes);
            report.add(r);
            switch (r.kind) {
                case TaskResult.FAILED -> throw new SceneException(r.text);
                case TaskResult.WRITTEN -> {
                    written.put(r.frame, r.text);
                    sizes.put(r.frame, r.bytes);
                }
                default -> tiles.computeIfAbsent(r.frame, f -> new ArrayList<>()).addAll(r.tiles);
            }
        }
        long assembly = System.nanoTime();
        for (Map.Entry<Integer, List<TilePixels>> frame : tiles.entrySet()) {
            Film film = new Film(settings.width(), settings.height());
            TileImage.assemble(frame.getValue(), settings.filter(), film);
            String target = job.output(frame.getKey());
            String name = new org.apache.hadoop.fs.Path(target).getName();
            sizes.put(frame.getKey(), Outputs.write(target, job.runId, hadoop,
                                                    o -> ImageWriters.encode(film, settings.exposure(), settings.srgb(), name, o)));
            written.put(frame.getKey(), target);
        }
        long assemblyNanos = System.nanoTime() - assembly;
        Outputs.removePartials(List.of(outputs), job.runId, hadoop);
        report.print(err, options.quiet(), written, sizes, new JobReport.Run(
            animation ? "frames " + range.first() + "-" + range.last() : "a still", scene == null ? "the default scene" : scene.toString(),
            settings.width(), settings.height(), settings.viewPlane().numSamples(), plan.size(), runs, progress.failedAttempts(2000), cores,
            System.nanoTime() - start, contextNanos, jobNanos, progress.firstStartNanos(), tiles.size(), assemblyNanos));
        return 0;
    }
}

package raytracer.cli;

import java.nio.file.Path;
import java.util.Map;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import raytracer.accel.Aggregation;
import raytracer.api.SceneOptions;
import raytracer.cache.MeshCache;
import raytracer.core.ViewPlane;
import raytracer.render.Workers;

/**
 * The options of a render that render, converge and the Spark job ({@code raytracer.spark.SparkRender})
 * share, as picocli reads them: declared here once (a mixin of each command), checked here once,
 * and made into the scene's options ({@link #sceneOptions}), which {@link raytracer.api.Scene}
 * applies by one path for all three. A command words an option its own way, where its meaning
 * there is narrower or wider, through its resource bundle under the option's description key.
 * Public for the Spark job, whose command line takes its options from render's.
 */
public final class RenderOptions {
    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    @Option(names = {"-W", "--width"}, paramLabel = "W", description = "Image width in pixels (overrides the scene).")
    Integer width;

    @Option(names = {"-H", "--height"}, paramLabel = "H", description = "Image height in pixels (overrides the scene).")
    Integer height;

    @Option(names = "--sampler", paramLabel = "NAME", completionCandidates = OptionNames.SamplerNames.class, descriptionKey = "sampler",
            description = "Sample pattern (overrides the scene): ${COMPLETION-CANDIDATES}.")
    String sampler;

    @Mixin
    FilterOptions filter = new FilterOptions();

    @Option(names = "--seed", paramLabel = "S", descriptionKey = "seed",
            description = "Random seed; the same seed gives the same image. Default: ${DEFAULT-VALUE}.")
    long seed = 1;

    @Option(names = {"-d", "--max-depth"}, paramLabel = "D",
            description = "Deepest recursion for mirror rays, 0 to " + ViewPlane.MAX_DEPTH + " (overrides the scene).")
    Integer maxDepth;

    @Option(names = "--cutoff", paramLabel = "C", descriptionKey = "cutoff",
            description = "Adaptive ray-tree cutoff (overrides the scene): branches weighing less than C and light "
                          + "samples adding less than C are not traced; 0 traces the whole tree.")
    Double cutoff;

    @Option(names = "--accel", paramLabel = "MODE", completionCandidates = OptionNames.AccelerationNames.class,
            description = "Search structure for the scene's objects: ${COMPLETION-CANDIDATES}. Default: auto (a BVH from "
                          + Aggregation.AUTO_THRESHOLD + " bounded objects on).")
    String accel = "auto";

    @Option(names = "--no-skip",
            description = "Render the scene as given, without the scene analysis: no light, object, term, ray or texture "
                          + "coordinate is left out, the max depth is the scene's (or --max-depth), every camera ray tests every "
                          + "object, and --accel auto counts every bounded object. The image is the same; this checks that.")
    boolean noSkip;

    @Option(names = "--cache-dir", paramLabel = "DIR",
            description = "Where parsed meshes and their BVHs are cached. Default: $XDG_CACHE_HOME/raytracer/meshes, "
                          + "or ~/.cache/raytracer/meshes.")
    Path cacheDir;

    @Option(names = "--cache-max", paramLabel = "SIZE",
            description = "The most the mesh cache's entries may take together, e.g. 512M or 4G; past it the least recently "
                          + "used are deleted. Default: $" + MeshCache.MAX_ENV + ", else 1G.")
    String cacheMax;

    @Option(names = "--no-cache", descriptionKey = "no-cache", description = "Parse and build every mesh, reading and writing no mesh cache.")
    boolean noCache;

    @Option(names = {"-t", "--threads"}, paramLabel = "T", descriptionKey = "threads",
            description = "Worker threads, 1 to " + Workers.MAX_THREADS + ". Default: all cores (${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = {"-q", "--quiet"}, descriptionKey = "quiet", description = "No progress bar and no summary line.")
    boolean quiet;

    @Option(names = {"-v", "--verbose"}, descriptionKey = "verbose", description = "Print stack traces with errors.")
    boolean verbose;

    /**
     * The options that change the scene, with {@code image}'s (null for a command without them:
     * converge measures many sample counts and radiance), checked and made plain; {@code costView}
     * is --view bvh-cost, an option of render's alone. A bad value is a usage error of the command,
     * found before any scene is read.
     */
    public SceneOptions sceneOptions(ImageOptions image, boolean costView) {
        if (cacheDir != null && cacheDir.toString().isEmpty()) {
            // an empty path is the working directory, which is no place for cache files
            throw usageError("--cache-dir must name a folder, got an empty name");
        }
        if (noCache && cacheDir != null) {
            throw usageError("--no-cache and --cache-dir exclude each other");
        }
        Path meshCache = noCache ? null
            : cacheDir != null ? cacheDir : MeshCache.defaultDir(System.getenv(), System.getProperty("user.home"));
        try {
            long meshCacheMax = cacheMax(cacheMax, System.getenv());
            return new SceneOptions(width, height, image == null ? null : image.samples, sampler, filter.choice(), maxDepth,
                                    image == null ? null : image.pass, cutoff, image == null ? null : image.encoding, null, accel,
                                    !noSkip, costView, seed, meshCache == null ? null : meshCache.toString(), meshCacheMax);
        } catch (IllegalArgumentException e) {
            throw usageError(e.getMessage());
        }
    }

    /**
     * The mesh cache's cap: --cache-max, else the environment's {@value MeshCache#MAX_ENV}, else
     * {@link MeshCache#DEFAULT_MAX_BYTES}; IllegalArgumentException names the source of a size
     * that does not parse.
     */
    static long cacheMax(String option, Map<String, String> environment) {
        String env = environment.get(MeshCache.MAX_ENV);
        String text = option != null ? option : env != null && !env.isBlank() ? env : null;
        if (text == null) {
            return MeshCache.DEFAULT_MAX_BYTES;
        }
        try {
            return MeshCache.parseSize(text);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException((option != null ? "--cache-max" : MeshCache.MAX_ENV) + ": " + e.getMessage());
        }
    }

    /** The worker threads (per task, on Spark), checked: the one place that holds --threads to its range. */
    public int threads() {
        if (threads < 1 || threads > Workers.MAX_THREADS) {
            throw usageError("--threads must be 1 to " + Workers.MAX_THREADS + ", got " + threads);
        }
        return threads;
    }

    /** True when -t was given; without it the Spark job gives each task its own cores. */
    public boolean threadsGiven() {
        return command.commandLine().getParseResult().hasMatchedOption("--threads");
    }

    public boolean quiet() {
        return quiet;
    }

    public boolean verbose() {
        return verbose;
    }

    /** True when neither --cache-dir nor --no-cache is given: the mesh cache is in the user's default folder (on each machine its own). */
    public boolean defaultMeshCache() {
        return cacheDir == null && !noCache;
    }

    /** True for --no-cache: no cache is read or written (converge keeps no reference either). */
    public boolean noCache() {
        return noCache;
    }

    private ParameterException usageError(String message) {
        return new ParameterException(command.commandLine(), message);
    }
}

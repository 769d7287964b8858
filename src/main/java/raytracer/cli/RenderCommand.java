package raytracer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raytracer.accel.Aggregation;
import raytracer.core.ViewPlane;
import raytracer.io.scene.MeshCache;
import raytracer.render.Workers;

/**
 * {@code render [SCENE] -o FILE ...}: the command's options as picocli reads them, and the program's
 * entry point. The options are checked by {@link OptionChecks}, the render is run by
 * {@link RenderRun}, and failures reach the user through {@link ErrorReport}.
 */
@Command(name = "render", mixinStandardHelpOptions = true, versionProvider = Version.class,
         sortOptions = false, subcommands = ConvergeCommand.class,
         description = "Renders a scene file (YAML or JSON) to PNG or PFM. Without SCENE, renders the built-in default scene.")
public final class RenderCommand implements Callable<Integer> {
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

    @Option(names = "--sampler", paramLabel = "NAME", completionCandidates = OptionNames.SamplerNames.class,
            description = "Sample pattern (overrides the scene): ${COMPLETION-CANDIDATES}.")
    String sampler;

    @Mixin
    FilterOptions filter = new FilterOptions();

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

    @Option(names = "--no-cache", description = "Parse and build every mesh, reading and writing no mesh cache.")
    boolean noCache;

    @Option(names = "--repeat", paramLabel = "N",
            description = "Render N times in this JVM and report each (benchmarking: the first render includes JIT warm-up).")
    int repeat = 1;

    @Option(names = "--show",
            description = "Show the image in a window as its tiles finish, as the file will hold it; the window stays "
                          + "until Esc or closed. Esc or closing it during the render cancels the render, as Ctrl-C does.")
    boolean show;

    @Option(names = "--stats", description = "Print a breakdown: load steps (parse, BVH build, mesh cache), render time, "
            + "rays by kind, BVH tests per ray, peak heap, and what the scene analysis left out and why.")
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
        return run(new PrintWriter(System.out, true), err, args);
    }

    /** As {@link #run(PrintWriter, String...)}, with standard output ({@code converge}'s table and {@code --csv -}) on {@code out}. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        return ErrorReport.install(new CommandLine(new RenderCommand()), out, err).execute(args);
    }

    @Override
    public Integer call() throws Exception {
        RenderRequest request = new OptionChecks(spec.commandLine()).check(this);
        return ErrorReport.explainingLimits(() -> new RenderRun(request, spec.commandLine()).run());
    }
}

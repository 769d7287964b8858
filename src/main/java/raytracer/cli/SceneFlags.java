package raytracer.cli;

import java.nio.file.Path;
import picocli.CommandLine;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import raytracer.accel.Aggregation;
import raytracer.api.SceneOptions;
import raytracer.core.ViewPlane;
import raytracer.cache.MeshCache;

/**
 * The options that change a scene's image or how it is searched and cached, as picocli reads them:
 * a mixin of {@code render} and of the Spark job ({@code raytracer.spark.SparkRender}), so both
 * spell, check and apply them alike ({@link #options}, {@link SceneOptions}).
 */
public final class SceneFlags {
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

    /** True when neither --cache-dir nor --no-cache is given: the mesh cache is in the user's default folder (on each machine its own). */
    public boolean defaultMeshCache() {
        return cacheDir == null && !noCache;
    }

    /**
     * The options checked and made plain ({@code costView}: --view bvh-cost, an option of render's
     * alone); a bad value is a usage error of {@code commandLine}, found before any scene is read.
     */
    public SceneOptions options(CommandLine commandLine, boolean costView) {
        OptionChecks checks = new OptionChecks(commandLine);
        if (cacheDir != null && cacheDir.toString().isEmpty()) {
            // an empty path is the working directory, which is no place for cache files
            throw new ParameterException(commandLine, "--cache-dir must name a folder, got an empty name");
        }
        if (noCache && cacheDir != null) {
            throw new ParameterException(commandLine, "--no-cache and --cache-dir exclude each other");
        }
        Path meshCache = noCache ? null
            : cacheDir != null ? cacheDir : MeshCache.defaultDir(System.getenv(), System.getProperty("user.home"));
        long meshCacheMax = checks.cacheMax(cacheMax, System.getenv());
        return checks.usage(() -> new SceneOptions(width, height, samples, sampler, filter.choice(), maxDepth, pass, cutoff, encoding,
                                                   accel, !noSkip, costView, seed, meshCache == null ? null : meshCache.toString(),
                                                   meshCacheMax));
    }
}

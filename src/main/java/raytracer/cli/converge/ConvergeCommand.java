package raytracer.cli.converge;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalInt;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raytracer.accel.Aggregation;
import raytracer.api.FilterChoice;
import raytracer.api.OutputFile;
import raytracer.cache.ReferenceCache;
import raytracer.cli.FilterOptions;
import raytracer.cli.Progress;
import raytracer.cli.Terminal;
import raytracer.cli.Version;
import raytracer.cli.render.RunReport;
import raytracer.core.RayTreeSettings;
import raytracer.core.Sampler;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.AtomicFile;
import raytracer.image.ErrorMetrics;
import raytracer.image.FileKind;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneFile;
import raytracer.io.scene.SceneLoader;
import raytracer.render.RenderStats;
import raytracer.render.Renderer;
import raytracer.render.Workers;
import raytracer.samplers.Samplers;

/**
 * {@code render converge SCENE ...}: renders a scene at several sample counts or time budgets, for
 * one or more configurations, measures each image's error against a reference and prints a table,
 * the slope of each curve, and a log-log plot of error against render time (issue 13).
 */
@Command(name = "converge", mixinStandardHelpOptions = true, versionProvider = Version.class, sortOptions = false,
         description = {"Renders SCENE at several sample counts (--spp) and/or time budgets (--time), for each configuration "
                        + "(--config), compares each image with a reference and prints a table of the errors; writes a log-log "
                        + "plot of relative RMSE against render time, one curve per configuration.",
                        "Seconds are the render's wall time (scene loading and BVH building excluded); before the timed renders "
                        + "of a configuration, one untimed render at its smallest sample count (at least 4) warms the JIT up."},
         footer = {"", "Metrics, over all pixels and the 3 channels of linear radiance times the scene's exposure (n values x_i, "
                   + "reference r_i):",
                   "  RMSE = sqrt(sum (x_i - r_i)^2 / n);  relative RMSE = RMSE / mean(r_i);",
                   "  relative MSE = sum ((x_i - r_i)^2 / (r_i^2 + 0.01)) / n (pbrt's; the 0.01 spares black pixels);",
                   "  worst pixel = the largest |x_i - r_i|, at (column, row) from the top left.",
                   "Slope: least squares of log(relative RMSE) against log(seconds); independent samples give -0.5."})
public final class ConvergeCommand implements Callable<Integer> {
    static final int WARM_UP_MIN_SPP = 4;
    static final int PLOT_WIDTH = 900;
    static final int PLOT_HEIGHT = 600;

    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file (.yaml, .yml or .json).")
    Path scene;

    @Option(names = {"-s", "--spp"}, split = ",", paramLabel = "N",
            description = "Sample counts per pixel, comma-separated (square patterns round up to a square). "
                          + "Default: 1,4,16,64 unless --time is given.")
    List<Integer> spp = new ArrayList<>();

    @Option(names = "--time", split = ",", paramLabel = "SECONDS",
            description = "Time budgets: for each, the sample count that the configuration's last render says fits in it.")
    List<Double> budgets = new ArrayList<>();

    @Option(names = "--config", paramLabel = "KEY=VALUE[,...]",
            description = "A configuration (repeat for more): sampler=NAME (a name --sampler takes), light-samples=N per "
                          + "area light, cutoff=C, label=TEXT; a/b in a value makes one configuration per alternative. "
                          + "Default: the scene's own settings.")
    List<String> configs = new ArrayList<>();

    @Option(names = "--reference", paramLabel = "REF",
            description = "auto (default: closed-form when the scene has an exact image, else self), closed-form, self "
                          + "(the scene rendered at --reference-spp, in two halves with other seeds whose difference measures "
                          + "its own noise, and cached), or a .pfm file of the image's size.")
    String reference = "auto";

    @Option(names = "--reference-spp", paramLabel = "N", description = "Samples per pixel of a self-rendered reference. Default: ${DEFAULT-VALUE}.")
    int referenceSpp = 4096;

    @Option(names = "--cache", paramLabel = "DIR",
            description = "Folder of self-rendered references. Default: $XDG_CACHE_HOME/raytracer/references or ~/.cache/raytracer/references.")
    Path cacheDir;

    @Option(names = "--no-cache", description = "Neither read nor write cached references.")
    boolean noCache;

    @Option(names = "--plot", paramLabel = "FILE.png", description = "The log-log plot. Default: <scene name>-convergence.png")
    Path plot;

    @Option(names = "--csv", paramLabel = "FILE",
            description = "Also write the table as comma-separated values; - writes them to standard output, alone (the table "
                          + "then goes to standard error).")
    Path csv;

    @Option(names = "--metric", paramLabel = "M",
            description = "What the errors are measured on: linear (radiance, as the .pfm output holds it; the default) or srgb "
                          + "(the display's values, clamped and sRGB-encoded, as a PNG holds them).")
    String metric = "linear";

    /** The filter of every curve and of a self-rendered reference. */
    @Mixin
    FilterOptions filter = new FilterOptions();

    @Option(names = "--frame", paramLabel = "N",
            description = "The frame of an animated scene to converge, from 0. Default: 0, the frame render renders without --frames.")
    int frame;

    @Option(names = {"-W", "--width"}, paramLabel = "W", description = "Image width (overrides the scene).")
    Integer width;

    @Option(names = {"-H", "--height"}, paramLabel = "H", description = "Image height (overrides the scene).")
    Integer height;

    @Option(names = {"-t", "--threads"}, paramLabel = "T", description = "Worker threads. Default: all cores (${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = "--seed", paramLabel = "S",
            description = "Seed of the measured renders; a self-rendered reference uses seeds made from it, never it. Default: ${DEFAULT-VALUE}.")
    long seed = 1;

    @Option(names = {"-q", "--quiet"}, description = "No progress, no notes: only the table.")
    boolean quiet;

    @Option(names = {"-v", "--verbose"}, description = "Print stack traces with errors.")
    boolean verbose;

    private static final String DISPLAYED = "the displayed values, clamped to [0, 1] and sRGB-encoded";

    /** --filter and --filter-stddev, checked. */
    private FilterChoice filterChoice = new FilterChoice(null, null);

    /** The run's one pool, open while {@link #converge} runs. */
    private Workers workers;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            return converge(err);
        } catch (CommandLine.ParameterException e) {
            throw e;
        } catch (Exception | OutOfMemoryError e) {
            String message = e instanceof OutOfMemoryError
                ? "out of memory; give Java more heap, e.g. java -Xmx8g -jar render.jar converge ..."
                : e.getMessage() == null || e.getMessage().isBlank() ? e.getClass().getSimpleName() : e.getMessage();
            err.println("render converge: error: " + Terminal.line(message));
            if (verbose) {
                e.printStackTrace(err);
            }
            return 1;
        }
    }

    private int converge(PrintWriter err) throws Exception {
        List<ConvergeConfig> curves = validate();
        try (Workers pool = new Workers(threads)) {
            workers = pool;
            return converge(curves, err);
        } finally {
            workers = null;
        }
    }

    private int converge(List<ConvergeConfig> curves, PrintWriter err) throws Exception {
        PrintWriter note = quiet ? new PrintWriter(PrintWriter.nullWriter()) : err;
        Path plotFile = plot != null ? plot : Path.of(stem(scene) + "-convergence.png");
        boolean csvToStdout = csv != null && csv.toString().equals("-");
        checkOutputs(plotFile, csvToStdout);
        boolean animated = checkFrame(note);
        LoadedScene base = load(ConvergeConfig.SCENE, err);
        checkNotInputs(base, plotFile, csvToStdout);
        ViewPlane vp = base.world().viewPlane();
        ConvergeReference.Image ref = reference(base, note);
        List<ConvergeRow> rows = new ArrayList<>();
        int total = curves.size() * (spp.size() + budgets.size());
        for (ConvergeConfig config : curves) {
            measure(config, ref.film(), vp.exposure(), rows, total, note);
        }
        // with --csv -, standard output is the CSV alone, and the table is a note
        PrintWriter out = csvToStdout ? note : spec.commandLine().getOut();
        out.print(ConvergeReport.table(rows));
        ConvergeReport.slopes(rows).forEach((name, slope) -> out.println(
            "slope of log error against log seconds, " + name + ": " + slope.describe()));
        // the reference's noise is known in linear units only
        double noise = displayedMetric() ? Double.NaN : ref.noiseRmse();
        out.println("reference: " + ref.what() + ConvergeReport.noiseNote(noise, rows.get(0).error().referenceMean()));
        if (displayedMetric()) {
            out.println("metric: " + DISPLAYED);
            note.println("converge: metric: " + DISPLAYED);
        }
        out.flush();
        if (csvToStdout) {
            PrintWriter stdout = spec.commandLine().getOut();
            stdout.print(ConvergeReport.csv(rows));
            stdout.flush();
        } else if (csv != null) {
            AtomicFile.write(csv, o -> o.write(ConvergeReport.csv(rows).getBytes(StandardCharsets.UTF_8)));
        }
        String title = scene.getFileName() + (animated ? " frame " + frame : "") + ": error against render time (" + vp.hres() + "x"
                       + vp.vres() + ", " + threads + " thread" + (threads == 1 ? "" : "s") + ")";
        ConvergeReport.chart(title, rows, noise).writePng(plotFile, PLOT_WIDTH, PLOT_HEIGHT);
        note.println("converge: plot written to " + plotFile);
        return 0;
    }

    /** Fails before the first render, not after the last, when an output could not be written: a usage error. */
    private void checkOutputs(Path plotFile, boolean csvToStdout) {
        usageIf(!plotFile.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png"),
                "cannot write " + plotFile + ": the plot is a PNG file, give a name ending in .png");
        String why = OutputFile.whyNotWritable(plotFile);
        usageIf(why != null, "cannot write " + plotFile + ": " + why);
        if (csv != null && !csvToStdout) {
            why = OutputFile.whyNotWritable(csv);
            usageIf(why != null, "cannot write " + csv + ": " + why);
            usageIf(OutputFile.same(csv, plotFile), "--plot and --csv name the same file, " + csv);
        }
    }

    /**
     * Refuses a --frame the scene does not have, a usage error; of an animated scene, says which
     * frame is converged, since a table of frame 0 alone could be taken for the animation's.
     * Returns whether the scene is animated.
     */
    private boolean checkFrame(PrintWriter note) throws SceneException {
        SceneFile file = SceneFile.read(scene, null);
        if (!file.animated()) {
            usageIf(frame != 0, "--frame " + frame + ": the scene has no animation section (a still is frame 0)");
            return false;
        }
        usageIf(frame < 0 || frame >= file.frames(), "--frame " + frame + ": the scene's animation has " + file.frames() + " frame"
                + (file.frames() == 1 ? "" : "s") + ", 0 to " + (file.frames() - 1));
        note.println("converge: the scene is animated; converging frame " + frame + " of its " + file.frames()
                     + (spec.commandLine().getParseResult().hasMatchedOption("--frame") ? "" : " (--frame N picks another)"));
        return true;
    }

    /** Refuses an output that the run reads: the scene, a file it reads, the --reference image. */
    private void checkNotInputs(LoadedScene base, Path plotFile, boolean csvToStdout) {
        Path referenceFile = reference.toLowerCase(Locale.ROOT).endsWith(".pfm") ? Path.of(reference) : null;
        List<Path> inputs = base.report().inputs();
        String why = OutputFile.whyInput(plotFile, scene, inputs, referenceFile);
        usageIf(why != null, "cannot write the plot " + plotFile + ": " + why);
        if (csv != null && !csvToStdout) {
            why = OutputFile.whyInput(csv, scene, inputs, referenceFile);
            usageIf(why != null, "cannot write the CSV " + csv + ": " + why);
        }
    }

    /** True when errors are taken on the displayed values ({@code --metric srgb}) rather than on radiance. */
    private boolean displayedMetric() {
        return metric.equals("srgb");
    }

    /** Checks the options; returns the configurations to measure. Bad values are usage errors (exit code 2). */
    private List<ConvergeConfig> validate() {
        if (spp.isEmpty() && budgets.isEmpty()) {
            spp = new ArrayList<>(List.of(1, 4, 16, 64));
        }
        for (int n : spp) {
            usageIf(n < 1 || n > Sampler.MAX_SAMPLES, "--spp values must be 1 to " + Sampler.MAX_SAMPLES + ", got " + n);
        }
        for (double t : budgets) {
            usageIf(!(t > 0) || Double.isInfinite(t), "--time values must be positive seconds, got " + t);
        }
        try {
            filterChoice = filter.choice();
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
        usageIf(!List.of("linear", "srgb").contains(metric), "--metric must be linear or srgb, got '" + metric + "'");
        // rendered in two halves of half the count each
        usageIf(referenceSpp < 1 || referenceSpp > 2 * Sampler.MAX_SAMPLES, "--reference-spp must be 1 to "
                + 2 * Sampler.MAX_SAMPLES + ", got " + referenceSpp);
        usageIf(threads < 1 || threads > Workers.MAX_THREADS, "--threads must be 1 to " + Workers.MAX_THREADS + ", got " + threads);
        usageIf(cacheDir != null && cacheDir.toString().isEmpty(), "--cache must name a folder, got an empty name");
        FileKind cacheKind = cacheDir == null ? FileKind.MISSING : FileKind.of(cacheDir);
        usageIf(cacheKind != FileKind.DIRECTORY && cacheKind != FileKind.MISSING,
                "--cache " + cacheDir + " is " + cacheKind.words() + ", not a folder");
        usageIf(width != null && width < 1, "--width must be at least 1, got " + width);
        usageIf(height != null && height < 1, "--height must be at least 1, got " + height);
        usageIf(!List.of("auto", "closed-form", "self").contains(reference) && !reference.toLowerCase(Locale.ROOT).endsWith(".pfm"),
                "--reference must be auto, closed-form, self or a .pfm file, got '" + reference + "'");
        spp = new ArrayList<>(new TreeSet<>(spp));
        budgets = new ArrayList<>(new TreeSet<>(budgets));
        if (configs.isEmpty()) {
            return List.of(ConvergeConfig.SCENE);
        }
        List<ConvergeConfig> curves = new ArrayList<>();
        for (String text : configs) {
            try {
                curves.addAll(ConvergeConfig.parse(text));
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
            }
        }
        return curves;
    }

    private void usageIf(boolean bad, String message) {
        if (bad) {
            throw new CommandLine.ParameterException(spec.commandLine(), message);
        }
    }

    /**
     * The scene with a configuration's overrides and the image size, prepared for rendering; its
     * warnings go to {@code warnings} unless that is null.
     */
    private LoadedScene load(ConvergeConfig config, PrintWriter warnings) throws SceneException {
        OptionalInt lightSamples = config.lightSamples() == null ? OptionalInt.empty() : OptionalInt.of(config.lightSamples());
        LoadedScene loaded = SceneLoader.load(scene, lightSamples, frame);
        World world = loaded.world();
        if (!quiet && warnings != null) {
            loaded.report().warnings().forEach(w -> warnings.println("render converge: warning: " + Terminal.line(w)));
        }
        ViewPlane vp = world.viewPlane();
        if (config.sampler() != null) {
            vp = vp.withSampler(Samplers.byName(config.sampler()));
        }
        vp = vp.withFilter(filterChoice.applyTo(vp.filter()));
        world.setViewPlane(vp.withResolution(width != null ? width : vp.hres(), height != null ? height : vp.vres()));
        RayTreeSettings rayTree = config.cutoff() != null ? loaded.rayTree().withCutoff(config.cutoff()) : loaded.rayTree();
        world.prepare(objects -> Aggregation.organize(objects, Aggregation.Mode.AUTO));
        return new LoadedScene(world, rayTree, loaded.encoding(), loaded.report());
    }

    private ConvergeReference.Image reference(LoadedScene base, PrintWriter note) throws Exception {
        ViewPlane vp = base.world().viewPlane();
        if (!List.of("auto", "closed-form", "self").contains(reference)) {
            Film film = ConvergeReference.fromFile(Path.of(reference), vp.hres(), vp.vres());
            note.println("converge: reference: " + reference);
            return new ConvergeReference.Image(film, Double.NaN, reference);
        }
        if (!vp.filter().isBox()) {
            // the exact images are averages over each pixel's square: a box-filtered image
            if (reference.equals("closed-form")) {
                throw new IOException("--reference closed-form: the exact image is of box-filtered pixels, and this run's filter is "
                                      + vp.filter().name() + "; use --filter box, or --reference self");
            }
            if (reference.equals("auto") && ConvergeReference.hasClosedForm(scene)) {
                note.println("converge: reference: the exact image is of box-filtered pixels, not " + vp.filter().name()
                             + "; rendering one instead");
            }
        } else if (!reference.equals("self")) {
            var exact = ConvergeReference.closedForm(scene, vp.hres(), vp.vres(), note, reference.equals("closed-form"));
            if (exact.isPresent()) {
                return exact.get();
            }
        }
        ReferenceCache cache = noCache ? null
            : new ReferenceCache(cacheDir != null ? cacheDir : ReferenceCache.defaultDir(System.getenv(), System.getProperty("user.home")));
        if (cache != null) {
            cache.checkFolder();
        }
        return ConvergeReference.rendered(scene, Files.readAllBytes(scene), frame, base, referenceSpp, ~seed, cache, this::render, note);
    }

    /** Renders one configuration: a warm-up, then each sample count and each time budget. */
    private void measure(ConvergeConfig config, Film ref, double exposure, List<ConvergeRow> rows, int total, PrintWriter note)
            throws SceneException {
        LoadedScene world = load(config, null);
        ViewPlane vp = world.world().viewPlane();
        String lights = ConvergeReport.lightSamples(world.world());
        String name = config.name(Samplers.nameOf(vp.sampler()), lights, world.rayTree().cutoff());
        int warmSpp = Math.max(WARM_UP_MIN_SPP, spp.isEmpty() ? 1 : spp.get(0));
        Film film = new Film(vp.hres(), vp.vres());
        RenderStats warm = render(withSamples(world, warmSpp), film, seed, name + ", warm-up");
        double secondsPerSpp = warm.seconds() / warm.samplesPerPixel();
        List<Integer> counts = new ArrayList<>(spp);
        for (int i = 0; i < counts.size() + budgets.size(); i++) {
            int n = i < counts.size() ? counts.get(i)
                : (int) Math.max(1, Math.min(1 << 20, Math.round(budgets.get(i - counts.size()) / secondsPerSpp)));
            RenderStats stats = render(withSamples(world, n), film, seed, name + ", " + n + " spp");
            secondsPerSpp = stats.seconds() / stats.samplesPerPixel();
            ErrorMetrics error = displayedMetric() ? ErrorMetrics.compareDisplayed(film, exposure, ref)
                : ErrorMetrics.compare(film, exposure, ref);
            rows.add(new ConvergeRow(name, stats.samplesPerPixel(), lights, stats.seconds(), error));
            String dropped = RunReport.droppedLine(stats);
            if (dropped != null) {
                // even with --quiet: the error measured is then of another image than the scene's
                spec.commandLine().getErr().println("render converge: warning: " + name + ", " + n + " spp: " + dropped);
            }
            note.printf(Locale.ROOT, "converge: [%d/%d] %s: %d spp, %.3f s, relative RMSE %.4g%n", rows.size(), total, name,
                        stats.samplesPerPixel(), stats.seconds(), error.relativeRmse());
        }
    }

    private static LoadedScene withSamples(LoadedScene scene, int n) {
        scene.world().setViewPlane(scene.world().viewPlane().withSamples(n));
        return scene;
    }

    /** One render into {@code film}, with a progress bar on a terminal. */
    private RenderStats render(LoadedScene scene, Film film, long renderSeed, String label) {
        Renderer renderer = new Renderer(scene.world(), scene.rayTree(), workers, renderSeed);
        if (quiet || System.console() == null) {
            return renderer.render(film);
        }
        Progress progress = new Progress(System.err, label, renderer::progress);
        try {
            return renderer.render(film);
        } finally {
            progress.close();
        }
    }

    private static String stem(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }
}

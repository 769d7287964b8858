package raytracer.cli.converge;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import raytracer.api.OutputFile;
import raytracer.api.Scene;
import raytracer.api.SceneFrame;
import raytracer.api.SceneOptions;
import raytracer.cache.ReferenceCache;
import raytracer.cli.Progress;
import raytracer.cli.Terminal;
import raytracer.cli.render.RunReport;
import raytracer.core.RayTreeSettings;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.AtomicFile;
import raytracer.image.ErrorMetrics;
import raytracer.image.Film;
import raytracer.io.scene.SceneFile;
import raytracer.render.RenderStats;
import raytracer.render.Renderer;
import raytracer.render.Workers;
import raytracer.samplers.Samplers;

/**
 * One run of {@code render converge}, its options checked ({@link ConvergeCommand}), on one pool of
 * --threads workers: the scene is made into a scene to render as render makes it ({@link Scene},
 * with the mesh cache), the reference chosen, each configuration loaded and prepared, rendered
 * once to warm up and then at each sample count and time budget, and the table, the CSV and the
 * plot written.
 */
final class ConvergeRun {
    static final int WARM_UP_MIN_SPP = 4;
    static final int PLOT_WIDTH = 900;
    static final int PLOT_HEIGHT = 600;
    private static final String DISPLAYED = "the displayed values, clamped to [0, 1] and sRGB-encoded";

    private final ConvergeCommand command;
    private final List<ConvergeConfig> curves;
    private final SceneOptions options;
    private final int threads;
    /** Where self-rendered references are kept, or null (--no-cache). */
    private final ReferenceCache cache;
    private final Path plotFile;
    private final PrintWriter err;
    /** Progress and notes on stderr; nothing with --quiet. */
    private final PrintWriter note;
    /** The run's one pool, open while {@link #run} runs. */
    private Workers workers;

    ConvergeRun(ConvergeCommand command, List<ConvergeConfig> curves, SceneOptions options, int threads, ReferenceCache cache,
                Path plotFile) {
        this.command = command;
        this.curves = curves;
        this.options = options;
        this.threads = threads;
        this.cache = cache;
        this.plotFile = plotFile;
        this.err = command.spec.commandLine().getErr();
        this.note = command.options.quiet() ? new PrintWriter(PrintWriter.nullWriter()) : err;
    }

    int run() throws Exception {
        try (Workers pool = new Workers(threads)) {
            workers = pool;
            return converge();
        } finally {
            workers = null;
        }
    }

    private int converge() throws Exception {
        Scene scene = Scene.open(command.scene, options);
        boolean animated = checkFrame(scene.file());
        SceneFrame base = scene.load(command.frame, workers);
        base.prepare(workers);
        if (!command.options.quiet()) {
            base.report().warnings().forEach(w -> err.println("render converge: warning: " + Terminal.line(w)));
        }
        checkNotInputs(base.report().inputs());
        ViewPlane vp = base.world().viewPlane();
        ConvergeReference.Image ref = ConvergeReference.choose(command, base, options.seed(), cache, this::render, note);
        List<ConvergeRow> rows = new ArrayList<>();
        int total = curves.size() * (command.spp.size() + command.budgets.size());
        for (ConvergeConfig config : curves) {
            measure(config, ref.film(), vp.exposure(), rows, total);
        }
        report(rows, ref, command.scene.getFileName() + (animated ? " frame " + command.frame : "") + ": error against render time ("
                          + vp.hres() + "x" + vp.vres() + ", " + threads + " thread" + (threads == 1 ? "" : "s") + ")");
        return 0;
    }

    /**
     * Refuses a --frame the scene does not have, a usage error; of an animated scene, says which
     * frame is converged, since a table of frame 0 alone could be taken for the animation's.
     * Returns whether the scene is animated.
     */
    private boolean checkFrame(SceneFile file) {
        int frame = command.frame;
        if (!file.animated()) {
            command.usageIf(frame != 0, "--frame " + frame + ": the scene has no animation section (a still is frame 0)");
            return false;
        }
        command.usageIf(frame < 0 || frame >= file.frames(), "--frame " + frame + ": the scene's animation has " + file.frames()
                        + " frame" + (file.frames() == 1 ? "" : "s") + ", 0 to " + (file.frames() - 1));
        note.println("converge: the scene is animated; converging frame " + frame + " of its " + file.frames()
                     + (command.spec.commandLine().getParseResult().hasMatchedOption("--frame") ? "" : " (--frame N picks another)"));
        return true;
    }

    /** Refuses an output that the run reads: the scene, a file it reads ({@code inputs}), the --reference image. */
    private void checkNotInputs(List<Path> inputs) {
        Path referenceFile = command.reference.toLowerCase(Locale.ROOT).endsWith(".pfm") ? Path.of(command.reference) : null;
        String why = OutputFile.whyInput(plotFile, command.scene, inputs, referenceFile);
        command.usageIf(why != null, "cannot write the plot " + plotFile + ": " + why);
        if (command.csv != null && !command.csvToStdout()) {
            why = OutputFile.whyInput(command.csv, command.scene, inputs, referenceFile);
            command.usageIf(why != null, "cannot write the CSV " + command.csv + ": " + why);
        }
    }

    /**
     * Renders one configuration, made into a scene to render with its sampler, cutoff and light
     * samples: a warm-up, then each sample count and each time budget.
     */
    private void measure(ConvergeConfig config, Film ref, double exposure, List<ConvergeRow> rows, int total) throws Exception {
        SceneFrame frame = Scene.open(command.scene, options.withSampling(config.sampler(), config.cutoff(), config.lightSamples()))
            .load(command.frame, workers);
        World world = frame.world();
        // named before the scene analysis, which may leave a light out: the settings asked for
        String lights = ConvergeReport.lightSamples(world);
        String name = config.name(Samplers.nameOf(world.viewPlane().sampler()), lights, frame.rayTree().cutoff());
        frame.prepare(workers);
        Film film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
        List<Integer> counts = command.spp;
        int warmSpp = Math.max(WARM_UP_MIN_SPP, counts.isEmpty() ? 1 : counts.get(0));
        RenderStats warm = render(withSamples(world, warmSpp), frame.rayTree(), options.seed(), film, name + ", warm-up");
        double secondsPerSpp = warm.seconds() / warm.samplesPerPixel();
        for (int i = 0; i < counts.size() + command.budgets.size(); i++) {
            int n = i < counts.size() ? counts.get(i)
                : (int) Math.max(1, Math.min(1 << 20, Math.round(command.budgets.get(i - counts.size()) / secondsPerSpp)));
            RenderStats stats = render(withSamples(world, n), frame.rayTree(), options.seed(), film, name + ", " + n + " spp");
            secondsPerSpp = stats.seconds() / stats.samplesPerPixel();
            ErrorMetrics error = command.displayedMetric() ? ErrorMetrics.compareDisplayed(film, exposure, ref)
                : ErrorMetrics.compare(film, exposure, ref);
            rows.add(new ConvergeRow(name, stats.samplesPerPixel(), lights, stats.seconds(), error));
            String dropped = RunReport.droppedLine(stats);
            if (dropped != null) {
                // even with --quiet: the error measured is then of another image than the scene's
                err.println("render converge: warning: " + name + ", " + n + " spp: " + dropped);
            }
            note.printf(Locale.ROOT, "converge: [%d/%d] %s: %d spp, %.3f s, relative RMSE %.4g%n", rows.size(), total, name,
                        stats.samplesPerPixel(), stats.seconds(), error.relativeRmse());
        }
    }

    private static World withSamples(World world, int n) {
        world.setViewPlane(world.viewPlane().withSamples(n));
        return world;
    }

    /** One render into {@code film}, with a progress bar on a terminal. */
    private RenderStats render(World world, RayTreeSettings rayTree, long seed, Film film, String label) {
        Renderer renderer = new Renderer(world, rayTree, workers, seed);
        if (command.options.quiet() || System.console() == null) {
            return renderer.render(film);
        }
        Progress progress = new Progress(System.err, label, renderer::progress);
        try {
            return renderer.render(film);
        } finally {
            progress.close();
        }
    }

    /** The table, the slopes and the reference's line (standard output, or stderr with --csv -), the CSV and the plot. */
    private void report(List<ConvergeRow> rows, ConvergeReference.Image ref, String title) throws IOException {
        boolean csvToStdout = command.csvToStdout();
        // with --csv -, standard output is the CSV alone, and the table is a note
        PrintWriter out = csvToStdout ? note : command.spec.commandLine().getOut();
        out.print(ConvergeReport.table(rows));
        ConvergeReport.slopes(rows).forEach((name, slope) -> out.println(
            "slope of log error against log seconds, " + name + ": " + slope.describe()));
        // the reference's noise is known in linear units only
        double noise = command.displayedMetric() ? Double.NaN : ref.noiseRmse();
        out.println("reference: " + ref.what() + ConvergeReport.noiseNote(noise, rows.get(0).error().referenceMean()));
        if (command.displayedMetric()) {
            out.println("metric: " + DISPLAYED);
            note.println("converge: metric: " + DISPLAYED);
        }
        out.flush();
        if (csvToStdout) {
            PrintWriter stdout = command.spec.commandLine().getOut();
            stdout.print(ConvergeReport.csv(rows));
            stdout.flush();
        } else if (command.csv != null) {
            AtomicFile.write(command.csv, o -> o.write(ConvergeReport.csv(rows).getBytes(StandardCharsets.UTF_8)));
        }
        ConvergeReport.chart(title, rows, noise).writePng(plotFile, PLOT_WIDTH, PLOT_HEIGHT);
        note.println("converge: plot written to " + plotFile);
    }
}

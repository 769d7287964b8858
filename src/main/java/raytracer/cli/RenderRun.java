package raytracer.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import raytracer.accel.Aggregation;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.DisplayEncoding;
import raytracer.image.FalseColor;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.MeshCache;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;
import raytracer.render.RenderStats;
import raytracer.render.Renderer;
import raytracer.render.SceneAnalysis;
import raytracer.render.TileListener;
import raytracer.render.Workers;
import raytracer.tracers.BvhCost;

/**
 * One run of the command, on one pool of --threads workers: loads the scene and prepares it on the
 * pool (so that the OBJ parse and the BVH builds fork onto its workers), applies the command-line
 * overrides, renders --repeat times with a progress bar (and with --show a {@link ShowWindow}), and
 * writes the image atomically. {@link RunReport} prints what it did.
 */
final class RenderRun {
    static final String DEFAULT_SCENE_RESOURCE = "/raytracer/scenes/default.yaml";

    private final RenderRequest request;
    private final RunReport report;
    /** The terminal's progress bar while the last render runs, for a cancel from the window to clear. */
    private volatile Progress progress;
    private final CommandLine commandLine;

    RenderRun(RenderRequest request, CommandLine commandLine) {
        this.request = request;
        this.commandLine = commandLine;
        this.report = new RunReport(commandLine.getErr(), request.repeat());
    }

    int run() throws Exception {
        HeapAfterCollections heap = request.stats() ? HeapAfterCollections.start() : null;
        try (Workers workers = new Workers(request.threads())) {
            long loadStart = System.nanoTime();
            LoadedScene loaded = workers.call(this::loadScene);
            long loadNanos = System.nanoTime() - loadStart;
            String input = OutputFile.whyInput(request.output(), request.scene(), loaded.report().inputs());
            if (input != null) {
                // found after loading, which names the inputs, and before rendering
                throw new ParameterException(commandLine, "cannot write " + request.output() + ": " + input);
            }
            int warned = loaded.report().warnings().size();
            if (!request.quiet()) {
                report.warnings(loaded.report().warnings());
            }
            World world = loaded.world();
            request.overrides().applyTo(world);
            RayTreeSettings rayTree = request.overrides().rayTree(loaded.rayTree());
            DisplayEncoding encoding = request.overrides().encoding(loaded.encoding());
            long prepareStart = System.nanoTime();
            // the cost view shows the search structure as the scene gives it, and --no-skip renders the
            // scene as given: without the analysis nothing is left out (the image is the same; --no-skip checks it)
            SceneAnalysis analysis = request.costView() || !request.analyse() ? null : SceneAnalysis.apply(world, rayTree);
            workers.call(() -> {
                world.prepare(objects -> Aggregation.organize(objects, request.accel()));
                return null;
            });
            long prepareNanos = System.nanoTime() - prepareStart;
            if (!request.quiet()) {
                // what preparing found: a cache entry that failed its checksum, one that could not be written
                List<String> warnings = loaded.report().warnings();
                report.warnings(warnings.subList(warned, warnings.size()));
            }
            if (request.costView()) {
                world.setTracer(BvhCost::new);
                // counts per pixel, not averages blurred over the neighbours
                world.setViewPlane(world.viewPlane().withFilter(PixelFilter.BOX));
            }
            ViewPlane vp = world.viewPlane();
            Film film = new Film(vp.hres(), vp.vres());
            // the file's codes: the cost view's false colour is written at exposure 1 through the sRGB curve
            double exposure = request.costView() ? 1 : vp.exposure();
            boolean srgb = request.costView() || encoding.srgbCurve();
            Renderer renderer = new Renderer(world, rayTree, workers, request.seed());
            // the window's type is named only here, so that without --show no AWT class is loaded
            try (ShowWindow window = request.show() ? openWindow(renderer, film, exposure, srgb) : null) {
                RenderStats stats = render(renderer, film, window);
                Film written = write(film, vp, exposure, srgb);
                report.droppedSamples(stats);
                if (window != null) {
                    window.finish(written);
                }
                if (!request.quiet()) {
                    report.summary(stats, request.output(), vp.filter());
                }
                if (request.stats()) {
                    report.stats(loaded.report(), world, loadNanos, prepareNanos, stats, heap);
                    report.skips(analysis, stats, request.costView() ? "the bvh-cost view shows the scene as given"
                        : "--no-skip: the scene analysis was off, the scene rendered as given");
                }
                if (window != null) {
                    window.awaitClose();
                }
            }
            return 0;
        }
    }

    /** The --show window on {@code film}, coding pixels as the file will. */
    private ShowWindow openWindow(Renderer renderer, Film film, double exposure, boolean srgb) throws Exception {
        String scene = request.scene() == null ? "default scene" : request.scene().getFileName().toString();
        return ShowWindow.open(scene, film, request.costView(), exposure, srgb, renderer::progress, this::cancel);
    }

    /**
     * Esc or the close button during the render (or the write): the run stops as on SIGINT, by the
     * same exit and status, so the shutdown hook deletes a temporary file being written and the
     * earlier output stays.
     */
    private void cancel() {
        Progress bar = progress;
        if (bar != null) {
            bar.close();
        }
        if (!request.quiet()) {
            report.cancelled(request.output());
        }
        Runtime.getRuntime().exit(ErrorReport.INTERRUPTED);
    }

    /**
     * Renders into {@code film}, after --repeat - 1 renders of the same frame that only report; the
     * last render tells {@code preview} (if not null) of each finished tile.
     */
    private RenderStats render(Renderer renderer, Film film, TileListener preview) {
        for (int i = 1; i < request.repeat(); i++) {
            report.repeat(i, renderer.render(new Film(film.width(), film.height())));
        }
        RenderStats stats;
        if (!request.quiet() && System.console() != null) {
            progress = new Progress(System.err, renderer::progress);
            try {
                stats = renderer.render(film, preview);
            } finally {
                progress.close();
                progress = null;
            }
        } else {
            stats = renderer.render(film, preview);
        }
        if (request.repeat() > 1) {
            report.repeat(request.repeat(), stats);
        }
        return stats;
    }

    /**
     * Writes the shaded image, or the cost view's false colour with its legend; returns the film
     * written (the false colour's, or {@code film}).
     */
    private Film write(Film film, ViewPlane vp, double exposure, boolean srgb) throws IOException {
        Film written = film;
        if (request.costView()) {
            // the film holds each pixel's mean over its samples
            double[] range = FalseColor.range(film);
            report.costLegend(range, vp.numSamples());
            written = FalseColor.apply(film, range[0], range[1]);
        }
        ImageWriters.write(written, exposure, srgb, request.output());
        return written;
    }

    private LoadedScene loadScene() throws SceneException, IOException {
        if (request.scene() != null) {
            return SceneLoader.load(request.scene(), request.meshCache() == null ? null : MeshCache.in(request.meshCache(), request.meshCacheMax()));
        }
        try (InputStream in = RenderRun.class.getResourceAsStream(DEFAULT_SCENE_RESOURCE)) {
            if (in == null) {
                throw new IOException("the embedded default scene is missing from the jar");
            }
            return SceneLoader.load("default scene", new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }
}

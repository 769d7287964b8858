package raytracer.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
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
import raytracer.render.Workers;
import raytracer.tracers.BvhCost;

/**
 * One run of the command, on one pool of --threads workers: loads the scene and prepares it on the
 * pool (so that the OBJ parse and the BVH builds fork onto its workers), applies the command-line
 * overrides, renders --repeat times with a progress bar, and writes the image atomically.
 * {@link RunReport} prints what it did.
 */
final class RenderRun {
    static final String DEFAULT_SCENE_RESOURCE = "/raytracer/scenes/default.yaml";

    private final RenderRequest request;
    private final RunReport report;
    private final CommandLine commandLine;

    RenderRun(RenderRequest request, CommandLine commandLine) {
        this.request = request;
        this.commandLine = commandLine;
        this.report = new RunReport(commandLine.getErr(), request.repeat());
    }

    int run() throws Exception {
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
            Film film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
            RenderStats stats = render(new Renderer(world, rayTree, workers, request.seed()), film);
            write(film, world.viewPlane(), encoding);
            report.droppedSamples(stats);
            if (!request.quiet()) {
                report.summary(stats, request.output(), world.viewPlane().filter());
            }
            if (request.stats()) {
                report.stats(loaded.report(), world, loadNanos, prepareNanos, stats);
                report.skips(analysis, stats, request.costView() ? "the bvh-cost view shows the scene as given"
                    : "--no-skip: the scene analysis was off, the scene rendered as given");
            }
            return 0;
        }
    }

    /** Renders into {@code film}, after --repeat - 1 renders of the same frame that only report. */
    private RenderStats render(Renderer renderer, Film film) {
        for (int i = 1; i < request.repeat(); i++) {
            report.repeat(i, renderer.render(new Film(film.width(), film.height())));
        }
        RenderStats stats;
        if (!request.quiet() && System.console() != null) {
            Progress progress = new Progress(System.err, renderer::progress);
            try {
                stats = renderer.render(film);
            } finally {
                progress.close();
            }
        } else {
            stats = renderer.render(film);
        }
        if (request.repeat() > 1) {
            report.repeat(request.repeat(), stats);
        }
        return stats;
    }

    /** Writes the shaded image, or the cost view's false colour with its legend. */
    private void write(Film film, ViewPlane vp, DisplayEncoding encoding) throws IOException {
        Path out = request.output();
        if (!request.costView()) {
            ImageWriters.write(film, vp.exposure(), encoding.srgbCurve(), out);
            return;
        }
        // the film holds each pixel's mean over its samples
        double[] range = FalseColor.range(film);
        report.costLegend(range, vp.numSamples());
        ImageWriters.write(FalseColor.apply(film, range[0], range[1]), 1, true, out);
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

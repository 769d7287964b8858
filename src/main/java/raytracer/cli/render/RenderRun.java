package raytracer.cli.render;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import raytracer.api.FrameRange;
import raytracer.api.ImageSettings;
import raytracer.api.OutputFile;
import raytracer.api.Scene;
import raytracer.api.SceneFrame;
import raytracer.cli.ErrorReport;
import raytracer.cli.Progress;
import raytracer.cli.show.ShowWindow;
import raytracer.image.FalseColor;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.render.RenderStats;
import raytracer.render.Renderer;
import raytracer.render.TileListener;
import raytracer.render.Workers;

/**
 * One run of the command, on one pool of --threads workers: reads the scene file once, then for
 * the still (or each frame of --frames) loads the world and prepares it on the pool (so that the
 * OBJ parse and the BVH builds fork onto its workers), applies the command-line overrides, renders
 * --repeat times with a progress bar (and with --show a {@link ShowWindow}), and writes the image
 * atomically. {@link RunReport} prints what it did.
 */
public final class RenderRun {
    private final RenderRequest request;
    private final RunReport report;
    /** The terminal's progress bar while the last render runs, for a cancel from the window to clear. */
    private volatile Progress progress;
    private final CommandLine commandLine;
    /** The warnings printed so far: each once, however many frames find it. */
    private final Set<String> printedWarnings = new HashSet<>();
    /** The film every frame is rendered into, and the --show window on it (null without). */
    private Film film;
    private ShowWindow window;
    /** The frame being rendered and its file, for the window's progress and a cancel's message. */
    private volatile Renderer renderer;
    private volatile Path current;
    /** The live heap's largest size after a collection, for --stats (null without it). */
    private HeapAfterCollections heap;

    public RenderRun(RenderRequest request, CommandLine commandLine) {
        this.request = request;
        this.commandLine = commandLine;
        this.report = new RunReport(commandLine.getErr(), request.repeat());
    }

    public int run() throws Exception {
        heap = request.stats() ? HeapAfterCollections.start() : null;
        try (Workers workers = new Workers(request.threads())) {
            long readStart = System.nanoTime();
            Scene scene = workers.call(() -> Scene.open(request.scene(), request.options()));
            long readNanos = System.nanoTime() - readStart;
            FrameRange range = request.frames() == null ? new FrameRange(0, 0) : request.frames();
            FrameOutputs outputs = null;
            if (request.frames() != null) {
                String why = range.whyNotIn(scene.file().frames(), scene.file().animated());
                if (why != null) {
                    throw new ParameterException(commandLine, "--frames " + range.first() + "-" + range.last() + ": " + why);
                }
                outputs = FrameOutputs.plan(commandLine, request.framePattern(), range, request.resume(), scene.image().width(),
                                            scene.image().height());
            }
            List<Integer> frames = outputs == null ? List.of(0) : outputs.frames();
            long start = System.nanoTime();
            int rendered = 0;
            try {
                for (int frame : frames) {
                    current = request.output(frame);
                    SceneFrame loaded = scene.load(frame, workers);
                    if (outputs != null && rendered == 0) {
                        // the first frame loaded names the inputs: the run is accepted, or refused before anything is made
                        outputs.checkNotInputs(request.scene(), loaded.report().inputs());
                        outputs.prepare();
                        // printed even with --quiet: a file that was there is replaced
                        report.warnings(outputs.redone());
                    }
                    renderFrame(loaded, frame, request.output(frame), workers, rendered == 0 ? readNanos : 0,
                                rendered == frames.size() - 1);
                    rendered++;
                }
                if (window != null) {
                    window.awaitClose();
                }
            } finally {
                if (window != null) {
                    window.close();
                }
            }
            if (request.frames() != null && !request.quiet()) {
                report.animation(scene.file().name(), range, rendered, readNanos, System.nanoTime() - start);
            }
            return 0;
        }
    }

    /**
     * Prepares, renders and writes frame {@code frame}, {@code loaded}, to {@code out};
     * {@code readNanos} is the time reading the file took, counted in the first frame's load.
     */
    private void renderFrame(SceneFrame loaded, int frame, Path out, Workers workers, long readNanos, boolean last) throws Exception {
        String input = OutputFile.whyInput(out, request.scene(), loaded.report().inputs());
        if (input != null) {
            // found after loading, which names the inputs, and before rendering
            throw new ParameterException(commandLine, "cannot write " + out + ": " + input);
        }
        int warned = loaded.report().warnings().size();
        warnings(loaded.report().warnings());
        loaded.prepare(workers);
        // what preparing found: a cache entry that failed its checksum, one that could not be written
        List<String> warnings = loaded.report().warnings();
        warnings(warnings.subList(warned, warnings.size()));
        ImageSettings image = loaded.image();
        // every frame has the same size: one film, which the --show window shows frame after frame
        if (film == null) {
            film = new Film(image.width(), image.height());
        }
        Renderer renderer = loaded.renderer(workers);
        this.renderer = renderer;
        String label = request.frames() == null ? "" : "frame " + frame;
        if (request.show()) {
            // the window's type is named only here, so that without --show no AWT class is loaded
            if (window == null) {
                window = openWindow(film, image.exposure(), image.srgb());
            }
            window.startFrame(label);
        }
        RenderStats stats = render(renderer, film, window, label);
        Film written = write(film, image, out);
        report.droppedSamples(stats);
        if (window != null && last) {
            window.finish(written);
        }
        if (!request.quiet()) {
            report.summary(stats, out, image.filter());
        }
        if (request.stats()) {
            report.stats(loaded.report(), loaded.world(), readNanos + loaded.loadNanos(), loaded.prepareNanos(), stats, heap);
            report.skips(loaded.analysis(), stats, request.options().costView() ? "the bvh-cost view shows the scene as given"
                : "--no-skip: the scene analysis was off, the scene rendered as given");
        }
    }

    /** Prints the warnings not printed before (the frames of an animation find the same ones); none with --quiet. */
    private void warnings(List<String> found) {
        if (request.quiet()) {
            return;
        }
        List<String> fresh = found.stream().filter(printedWarnings::add).toList();
        report.warnings(fresh);
    }

    /** The --show window on {@code film}, coding pixels as the file will, telling the progress of the frame being rendered. */
    private ShowWindow openWindow(Film film, double exposure, boolean srgb) throws Exception {
        String scene = request.scene() == null ? "default scene" : request.scene().getFileName().toString();
        return ShowWindow.open(scene, film, request.options().costView(), exposure, srgb, () -> renderer.progress(), this::cancel);
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
            report.cancelled(current);
        }
        Runtime.getRuntime().exit(ErrorReport.INTERRUPTED);
    }

    /**
     * Renders into {@code film}, after --repeat - 1 renders of the same frame that only report; the
     * last render tells {@code preview} (if not null) of each finished tile. {@code label} names
     * the frame on the progress bar.
     */
    private RenderStats render(Renderer renderer, Film film, TileListener preview, String label) {
        for (int i = 1; i < request.repeat(); i++) {
            report.repeat(i, renderer.render(new Film(film.width(), film.height())));
        }
        RenderStats stats;
        if (!request.quiet() && System.console() != null) {
            progress = new Progress(System.err, label, renderer::progress);
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
     * Writes the shaded image, or the cost view's false colour with its legend, to {@code out};
     * returns the film written (the false colour's, or {@code film}).
     */
    private Film write(Film film, ImageSettings image, Path out) throws IOException {
        Film written = film;
        if (request.options().costView()) {
            // the film holds each pixel's mean over its samples
            double[] range = FalseColor.range(film);
            report.costLegend(range, image.viewPlane().numSamples());
            written = FalseColor.apply(film, range[0], range[1]);
        }
        ImageWriters.write(written, image.exposure(), image.srgb(), out);
        return written;
    }
}

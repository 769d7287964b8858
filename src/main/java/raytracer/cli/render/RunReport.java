package raytracer.cli.render;

import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Path;
import java.util.List;
import raytracer.accel.ObjectBVH;
import raytracer.api.FrameRange;
import raytracer.cli.Terminal;
import raytracer.core.PixelFilter;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.World;
import raytracer.io.scene.LoadReport;
import raytracer.render.RenderStats;
import raytracer.render.SceneAnalysis;

/**
 * What a run prints on stderr besides errors: the scene's warnings, a line per --repeat render,
 * the bvh-cost view's legend, the summary line and the --stats breakdown.
 */
public final class RunReport {
    private final PrintWriter err;
    private final int repeat;

    RunReport(PrintWriter err, int repeat) {
        this.err = err;
        this.repeat = repeat;
    }

    void warnings(List<String> warnings) {
        warnings.forEach(w -> err.println("render: warning: " + Terminal.line(w)));
    }

    void repeat(int i, RenderStats s) {
        err.printf("render %d of %d: %.3f s, %.2f M rays/s%n", i, repeat, s.seconds(), s.raysPerSecond() / 1e6);
    }

    /** The cost view's scale, {@code range} from black to white; printed even with --quiet, as it is the image's legend. */
    void costLegend(double[] range, int samples) {
        String format = samples == 1 ? "%.0f" : "%.1f";
        err.printf("bvh-cost: " + format + " to " + format + " bounding-volume tests per %s (black to white)%n",
                   range[0], range[1], samples == 1 ? "pixel" : "ray, averaged over each pixel");
    }

    /**
     * The end of --frames: how many frames were rendered and how many were already complete, the
     * wall time, and the scene file's one read apart from the frames' time.
     */
    void animation(String scene, FrameRange range, int rendered, long readNanos, long framesNanos) {
        int skipped = range.count() - rendered;
        err.printf("render: frames %d-%d of %s: %d rendered%s in %.2f s (%.2f s a frame), the scene file read once in %.3f s%n",
                   range.first(), range.last(), scene, rendered, skipped == 0 ? "" : ", " + skipped + " already complete (--resume)",
                   framesNanos / 1e9, rendered == 0 ? 0 : framesNanos / 1e9 / rendered, readNanos / 1e9);
    }

    /** A render cancelled from the --show window; whatever {@code out} held before is kept. */
    void cancelled(Path out) {
        err.println("render: cancelled from the window; " + out + " left as it was");
    }

    /** The summary line, naming the pixel filter when it is not the book's box (the image is then softer). */
    void summary(RenderStats s, Path out, PixelFilter filter) {
        err.println(summaryLine(s, out) + (filter.isBox() ? "" : String.format(", %s filter of radius %s pixels", filter.name(),
                                                                                        filter.radius())));
    }

    static String summaryLine(RenderStats s, Path out) {
        return String.format("%s: %dx%d, %d spp, %d thread%s, %.2f s, %.2f M rays/s (%d primary, %d shadow, %d secondary)",
            out, s.width(), s.height(), s.samplesPerPixel(), s.threads(), s.threads() == 1 ? "" : "s",
            s.seconds(), s.raysPerSecond() / 1e6, s.primaryRays(), s.shadowRays(), s.secondaryRays());
    }

    /**
     * The samples the render dropped as not finite, a warning line printed even with --quiet: the
     * image is then not what the scene describes (a defect to report), and must not pass unseen.
     */
    void droppedSamples(RenderStats s) {
        String line = droppedLine(s);
        if (line != null) {
            err.println("render: warning: " + line);
        }
    }

    /** The warning about dropped samples, or null when none were. */
    public static String droppedLine(RenderStats s) {
        if (s.nonFiniteSamples() == 0) {
            return null;
        }
        return s.nonFiniteSamples() + " non-finite sample" + (s.nonFiniteSamples() == 1 ? "" : "s")
               + " (NaN or infinite radiance) dropped; the pixels they fell in average the others";
    }

    /** The --stats breakdown: load steps and mesh figures, preparation, rays by kind, box tests, peak heap. */
    void stats(LoadReport load, World world, long loadNanos, long prepareNanos, RenderStats s, HeapAfterCollections heap) {
        err.printf("stats: load scene %.3f s", loadNanos / 1e9);
        load.timings().forEach((step, nanos) -> err.printf(" (%s %.3f s)", step, nanos / 1e9));
        err.println();
        load.statistics().forEach(line -> err.println("stats: " + line));
        boolean topLevelBvh = world.searched().stream().anyMatch(ObjectBVH.class::isInstance);
        err.printf("stats: prepare (%s) %.3f s", topLevelBvh ? "top-level BVH" : "objects in a list", prepareNanos / 1e9);
        load.prepareTimings().forEach((step, nanos) -> err.printf(" (%s %.3f s)", step, nanos / 1e9));
        err.printf(", render %.3f s%n", s.seconds());
        err.printf("stats: rays %d (primary %d, shadow %d, secondary %d), %.2f M rays/s%n",
                   s.totalRays(), s.primaryRays(), s.shadowRays(), s.secondaryRays(), s.raysPerSecond() / 1e6);
        long afterCollections = heap.largestBytes();
        err.printf("stats: %.1f bounding-volume tests (BVH node boxes examined) per ray, peak heap %.0f MiB (%s)%n",
                   s.boxTestsPerRay(), peakHeapBytes() / (1024.0 * 1024.0), afterCollections < 0 ? "no collection ran"
                   : String.format("largest after a collection %.0f MiB, %d collections", afterCollections / (1024.0 * 1024.0),
                                   heap.collections()));
    }

    /**
     * What the scene analysis left out, one line per decision with its reason; the count of what a
     * kind of decision saved ends its only line, or follows its last. Without an analysis, one
     * line says why none ran ({@code whyNone}).
     */
    void skips(SceneAnalysis analysis, RenderStats s, String whyNone) {
        if (analysis == null) {
            err.println("stats: skip: nothing (" + whyNone + ")");
            return;
        }
        List<Skip> skips = analysis.skips();
        if (skips.isEmpty()) {
            err.println("stats: skip: nothing (every term, ray and object of the scene may change the image)");
        }
        for (int i = 0; i < skips.size(); i++) {
            Skip skip = skips.get(i);
            int kind = skip.counter();
            long sameKind = skips.stream().filter(k -> k.counter() == kind).count();
            String saved = kind == Skipped.UNCOUNTED ? "" : String.format(" (saves %,d %s)", s.skipped(kind), Skipped.name(kind));
            err.printf("stats: skip: %s: %s%s%n", skip.what(), skip.why(), sameKind == 1 ? saved : "");
            boolean lastOfKind = skips.subList(i + 1, skips.size()).stream().noneMatch(k -> k.counter() == kind);
            if (sameKind > 1 && lastOfKind && kind != Skipped.UNCOUNTED) {
                err.printf("stats: skip: together these save %,d %s%n", s.skipped(kind), Skipped.name(kind));
            }
        }
    }

    /**
     * The sum of the peak usage of the heap's memory pools since the JVM started: each pool's largest
     * use when sampled (at the start and end of every collection, and now), garbage included, so the
     * young pool counts as much as it was allowed to fill. {@link HeapAfterCollections} gives the
     * live side.
     */
    static long peakHeapBytes() {
        long peak = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                peak += pool.getPeakUsage().getUsed();
            }
        }
        return peak;
    }
}

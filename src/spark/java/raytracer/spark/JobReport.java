package raytracer.spark;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * What the driver learns from its tasks' results and prints at the end of a job: the non-finite
 * samples dropped (a warning, even with -q), the files written, the summary line, and the timings
 * the model of docs/distributed.md is made of (scene reads, the tasks' own time, the driver's part).
 */
final class JobReport {
    /** Where each side found SnakeYAML: the executors', and the driver's once {@link #print} adds it. */
    private final Set<String> yaml = new TreeSet<>();
    private long nonFinite;
    private long taskNanos;
    private long renderNanos;
    private long sceneNanos;
    private int sceneReads;

    /** Counts one task's result in. */
    void add(TaskResult r) {
        yaml.add(r.yaml);
        nonFinite += r.nonFiniteSamples;
        taskNanos += r.taskNanos;
        renderNanos += r.renderNanos;
        sceneNanos += r.sceneNanos;
        sceneReads += r.sceneNanos > 0 ? 1 : 0;
    }

    /** How the job ran: what it rendered and how it was split, and the times it took. */
    record Run(String what, String scene, int width, int height, int samples, int tasks, int runs, int failedAttempts, int cores,
               long nanos, long contextNanos, long jobNanos, long firstStartNanos, int framesAssembled, long assemblyNanos) {
    }

    /** Prints the warning, and unless {@code quiet} the files {@code written} (by frame, with their {@code sizes}) and the summary. */
    void print(PrintWriter err, boolean quiet, Map<Integer, String> written, Map<Integer, Long> sizes, Run run) {
        if (nonFinite > 0) {
            err.println("render-spark: warning: " + nonFinite + " non-finite sample" + (nonFinite == 1 ? "" : "s")
                        + " (NaN or infinite radiance) dropped; the pixels they fell in average the others");
        }
        if (quiet) {
            return;
        }
        written.forEach((f, file) -> err.printf("render-spark: wrote %s (%,d bytes)%n", file, sizes.get(f)));
        yaml.add("driver " + FrameTask.yamlSource());
        err.println(summary(run));
        err.printf(Locale.ROOT, "render-spark: timings: job %.3f s, first task started after %.3f s, tasks %.3f s in all "
                   + "(%.1f ms a task, %.1f ms of it rendering), %d scene read%s on executors (%.3f s each), %s put together and "
                   + "written by the driver in %.3f s%n",
                   run.jobNanos() / 1e9, run.firstStartNanos() / 1e9, taskNanos / 1e9, taskNanos / 1e6 / run.tasks(),
                   renderNanos / 1e6 / run.tasks(), sceneReads, sceneReads == 1 ? "" : "s",
                   sceneReads == 0 ? 0 : sceneNanos / 1e9 / sceneReads,
                   run.framesAssembled() == 1 ? "1 frame" : run.framesAssembled() + " frames", run.assemblyNanos() / 1e9);
    }

    private String summary(Run run) {
        String split = run.runs() == 1 ? "a task per frame" : run.runs() + " tile runs per frame";
        TreeSet<String> executors = new TreeSet<>();
        String driver = "";
        for (String y : yaml) {
            if (y.startsWith("driver ")) {
                driver = y.substring("driver ".length());
            } else {
                executors.add(y);
            }
        }
        return String.format(Locale.ROOT, "render-spark: %s of %s, %dx%d, %d spp: %d tasks (%s, %d failed attempt%s retried) "
                             + "on %d cores in %s (the Spark context started in %.3f s); SnakeYAML from %s on the driver, from %s on "
                             + "the executors", run.what(), run.scene(), run.width(), run.height(), run.samples(), run.tasks(), split,
                             run.failedAttempts(), run.failedAttempts() == 1 ? "" : "s", run.cores(), Progress.time(run.nanos() / 1e9),
                             run.contextNanos() / 1e9, driver, String.join(" and ", executors));
    }
}

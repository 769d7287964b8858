package raytracer.spark;

import java.io.PrintWriter;
import java.util.HashSet;
import java.util.Locale;
import java.util.Set;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerTaskEnd;
import org.apache.spark.scheduler.SparkListenerTaskStart;

/**
 * The driver's progress line: tasks done of the job's (a task counted once, however many attempts
 * it took), elapsed time and the time left at the rate so far, printed as a plain line at most
 * every {@link #EVERY_NANOS} when something changed, so a log of the run reads well too; a job
 * shorter than that prints none (its summary follows at once, or its error alone). It also
 * counts the attempts that failed (a killed executor's tasks, a test's hook), which Spark retried.
 */
final class Progress extends SparkListener {
    static final long EVERY_NANOS = 2_000_000_000L;

    private final PrintWriter err;
    private final int total;
    private final String unit;
    private final boolean quiet;
    private final long start = System.nanoTime();
    private final Set<Integer> done = new HashSet<>();
    private int failedAttempts;
    private long printed = start;
    private long firstStart = -1;

    /** Reports on {@code err} (nothing when {@code quiet}) the {@code total} tasks of the job, each rendering a {@code unit}. */
    Progress(PrintWriter err, int total, String unit, boolean quiet) {
        this.err = err;
        this.total = total;
        this.unit = unit;
        this.quiet = quiet;
    }

    @Override
    public synchronized void onTaskStart(SparkListenerTaskStart task) {
        if (firstStart < 0) {
            firstStart = System.nanoTime() - start;
        }
    }

    /** How long after the job was submitted its first task started (executors being launched, or waited for); -1 before. */
    synchronized long firstStartNanos() {
        return firstStart;
    }

    @Override
    public synchronized void onTaskEnd(SparkListenerTaskEnd end) {
        if (!end.taskInfo().successful()) {
            failedAttempts++;
            return;
        }
        if (!done.add(end.taskInfo().index())) {
            return;
        }
        notifyAll();
        long now = System.nanoTime();
        boolean first = printed == start;
        if (!quiet && (now - printed >= EVERY_NANOS || done.size() == total && !first)) {
            printed = now;
            err.println(line(done.size(), now - start));
        }
    }

    String line(int finished, long elapsedNanos) {
        double seconds = elapsedNanos / 1e9;
        String left = finished == total ? "done" : "about " + time(seconds * (total - finished) / finished) + " left";
        return String.format(Locale.ROOT, "render-spark: %d of %d %s (%.0f%%), %s, %s", finished, total, unit, 100.0 * finished / total,
                             time(seconds), left);
    }

    /**
     * The attempts that failed, once the listener has seen every task end (Spark tells listeners
     * after the job's result is in, in the order things happened, so a failure is told before the
     * success of its retry), or after {@code waitMillis}.
     */
    synchronized int failedAttempts(long waitMillis) throws InterruptedException {
        long until = System.currentTimeMillis() + waitMillis;
        while (done.size() < total && System.currentTimeMillis() < until) {
            wait(20);
        }
        return failedAttempts;
    }

    static String time(double s) {
        if (s < 60) {
            return String.format(Locale.ROOT, "%.1f s", s);
        }
        long total = Math.round(s);
        return String.format(Locale.ROOT, "%dm%02ds", total / 60, total % 60);
    }
}

package raytracer.tools.studies;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import raytracer.image.chart.Bar;
import raytracer.image.chart.BarChart;
import raytracer.image.chart.LogLogChart;
import raytracer.image.chart.Series;

/**
 * The figures of docs/distributed.md from the runs tools/studies/spark-measure/run wrote: the wall
 * times and their ratios round by round, the cost of a task, and a model of a render on N one-core
 * executors made of those figures alone, checked against the two-worker cluster's measured time.
 * Prints the figures as Markdown and draws two charts with the project's own chart code.
 *   tools/studies/spark-measure/spark-model docs/distributed/measurements.tsv docs/figures
 */
public final class SparkModel {
    /** The turntable of the Spark measurements: its frame count, and the still's pixels and samples. */
    private static final int FRAMES = 120;
    private static final double STILL_SAMPLES = 960.0 * 640 * 64;
    /** The poster the model is asked about: 8k (7680x4320) at 256 samples a pixel. */
    private static final double POSTER_PIXELS = 7680.0 * 4320;
    private static final double POSTER_SAMPLES = POSTER_PIXELS * 256;
    private static final double STILL_PIXELS = 960.0 * 640;
    /** Cores of the machine the figures were measured on (the measurements' one JVM renders on 2 threads). */
    private static final int CORES = 2;
    /** SparkRender's default for a still: three tile runs per core. */
    private static final int RUNS_PER_CORE = 3;

    record Run(int round, String workload, String mode, double process, double time, double context, double firstTask, double tasks,
               int sceneReads, double sceneRead, double driver, boolean identical) {
    }

    public static void main(String[] args) throws IOException {
        List<Run> runs = read(Path.of(args[0]));
        Path figures = Path.of(args[1]);
        int rounds = runs.stream().mapToInt(Run::round).max().orElse(0);
        StringBuilder md = new StringBuilder();
        md.append(String.format(Locale.ROOT, "%d rounds; every Spark output byte-identical to render's: %s%n%n", rounds,
                                runs.stream().allMatch(Run::identical) ? "yes" : "NO"));

        // the ratio twice: with the job's wait for its first task (the driver's reading of the scene,
        // executors launched) counted in, and counted as startup as render's JVM start and scene read are
        md.append("| workload | mode | job s (mean) | range | ratio to one JVM, each round | the same, first-task wait as startup "
                  + "| startup s: process - job (of it, context) | first task after s |\n");
        md.append("|---|---|---|---|---|---|---|---|\n");
        List<Bar> bars = new ArrayList<>();
        for (String workload : List.of("turntable", "still")) {
            for (String mode : List.of("jvm", "local", "cluster")) {
                List<Run> these = select(runs, workload, mode);
                if (these.isEmpty()) {
                    continue;
                }
                double[] time = these.stream().mapToDouble(Run::time).toArray();
                StringBuilder ratios = new StringBuilder();
                StringBuilder working = new StringBuilder();
                for (Run r : these) {
                    Run jvm = one(runs, r.round, workload, "jvm");
                    ratios.append(ratios.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.3f", r.time / jvm.time));
                    working.append(working.length() == 0 ? "" : ", ")
                        .append(String.format(Locale.ROOT, "%.3f", (r.time - r.firstTask) / jvm.time));
                }
                double startup = mean(these.stream().mapToDouble(r -> r.process - r.time).toArray());
                double context = mean(these.stream().mapToDouble(Run::context).toArray());
                md.append(String.format(Locale.ROOT, "| %s | %s | %.2f | %.2f-%.2f | %s | %s | %.2f (%.2f) | %.2f |%n", workload, name(mode),
                                        mean(time), min(time), max(time), ratios, working, startup, context,
                                        mean(these.stream().mapToDouble(Run::firstTask).toArray())));
                bars.add(new Bar(name(mode), label(workload), mean(time), (max(time) - min(time)) / 2));
            }
        }

        // Spark's cost of a task: the same image as 400 tile runs and as 8, the difference in
        // core-seconds spread over the 392 extra tasks; the part spent inside our task code apart
        md.append("\n| cost of a task | wall, core-ms a task | inside the task, ms a task |\n|---|---|---|\n");
        Map<String, Double> overhead = new LinkedHashMap<>();
        for (String mode : List.of("local", "cluster")) {
            double wall = 0;
            double inside = 0;
            for (int round = 1; round <= rounds; round++) {
                Run many = one(runs, round, "tasks-400", mode);
                Run few = one(runs, round, "tasks-8", mode);
                wall += (many.time - many.firstTask - (few.time - few.firstTask)) * CORES / 392 / rounds;
                inside += (many.tasks - few.tasks) / 392 / rounds;
            }
            overhead.put(mode, wall);
            md.append(String.format(Locale.ROOT, "| %s | %.1f | %.1f |%n", name(mode), wall * 1000, inside * 1000));
        }

        // the model: everything from one JVM's render time and the task cost above; executor launch
        // and the scene's read per executor from the cluster's own reports
        double frame = CORES * mean(select(runs, "turntable", "jvm").stream().mapToDouble(Run::time).toArray()) / FRAMES;
        double sample = CORES * mean(select(runs, "still", "jvm").stream().mapToDouble(Run::time).toArray()) / STILL_SAMPLES;
        List<Run> cluster = select(runs, "turntable", "cluster");
        double launch = mean(cluster.stream().mapToDouble(Run::firstTask).toArray());
        double sceneRead = mean(cluster.stream().mapToDouble(Run::sceneRead).toArray());
        double task = overhead.get("cluster");
        List<Run> stills = select(runs, "still", "cluster");
        double assemblyPerPixel = mean(stills.stream().mapToDouble(Run::driver).toArray()) / STILL_PIXELS;
        md.append(String.format(Locale.ROOT, "%nModel inputs: %.3f core-s a frame, %.3g core-s a sample (still), %.2f s to the first task "
                                + "(executors launched), %.3f s scene read per executor, %.1f ms a task, driver assembly %.3g s a pixel%n%n",
                                frame, sample, launch, sceneRead, task * 1000, assemblyPerPixel));
        md.append("| executors | 120-frame turntable s | 8k 256-spp still s | of which driver assembly s |\n|---|---|---|---|\n");
        int[] executors = {1, 2, 5, 10, 20, 50, 100};
        double[] n = new double[executors.length];
        double[] animation = new double[executors.length];
        double[] poster = new double[executors.length];
        double[] ideal = new double[executors.length];
        for (int i = 0; i < executors.length; i++) {
            int e = executors[i];
            n[i] = e;
            animation[i] = launch + sceneRead + Math.ceil((double) FRAMES / e) * (frame + task);
            int tasks = RUNS_PER_CORE * e;
            double assembly = assemblyPerPixel * POSTER_PIXELS;
            poster[i] = launch + sceneRead + RUNS_PER_CORE * (sample * POSTER_SAMPLES / tasks + task) + assembly;
            ideal[i] = sample * POSTER_SAMPLES / e;
            md.append(String.format(Locale.ROOT, "| %d | %.1f | %.1f | %.1f |%n", e, animation[i], poster[i], assembly));
        }
        double measured = mean(cluster.stream().mapToDouble(Run::time).toArray());
        double measuredStill = mean(stills.stream().mapToDouble(Run::time).toArray());
        double predictedStill = launch + sceneRead + RUNS_PER_CORE * (sample * STILL_SAMPLES / (RUNS_PER_CORE * 2) + task)
                                + assemblyPerPixel * STILL_PIXELS;
        md.append(String.format(Locale.ROOT, "%nCheck on the two-worker cluster: turntable predicted %.1f s, measured %.1f s (%.2fx); "
                                + "still predicted %.1f s, measured %.1f s (%.2fx)%n", animation[1], measured, measured / animation[1],
                                predictedStill, measuredStill, measuredStill / predictedStill));
        // where a still pays off: N executors beat this machine's 2 cores once the still's work W
        // (core-seconds) makes W / 2 > S + W / N, S the cluster's fixed cost (spark-submit's start,
        // the context, executors launched, the scene read): W > S / (1/2 - 1/N)
        double fixed = mean(stills.stream().mapToDouble(r -> r.process - r.time + r.firstTask + r.sceneRead).toArray());
        md.append(String.format(Locale.ROOT, "%nWhere a still pays off: fixed cost S of a cluster job %.1f s; ", fixed));
        for (int e : new int[] {10, 100}) {
            double work = fixed / (1.0 / CORES - 1.0 / e);
            md.append(String.format(Locale.ROOT, "on %d executors from %.0f core-s of work (%.1f s on this machine's 2 cores; "
                                    + "8k at %.1f spp)%s", e, work, work / CORES, work / sample / POSTER_PIXELS, e == 10 ? "; " : "\n"));
        }
        bars.add(new Bar("model, two workers", label("turntable"), animation[1], 0));
        bars.add(new Bar("model, two workers", label("still"), predictedStill, 0));
        System.out.print(md);

        new BarChart("The same 2 cores: job time without startup (mean of " + rounds + " rounds, bars: range)", "", "seconds", bars)
            .writePng(figures.resolve("distributed-times.png"), 820, 460);
        new LogLogChart("Model: wall time on N one-core executors", "executors", "seconds",
                        List.of(new Series("120-frame turntable 480x360, 4 spp", n, animation),
                                new Series("8k still, 256 spp", n, poster),
                                new Series("measured turntable, two workers", new double[] {2}, new double[] {measured}),
                                new Series("8k still, work alone (no overheads)", n, ideal, true)))
            .writePng(figures.resolve("distributed-model.png"), 820, 520);
    }

    private static List<Run> read(Path file) throws IOException {
        List<Run> runs = new ArrayList<>();
        for (String line : Files.readAllLines(file)) {
            String[] f = line.split("\t");
            if (f.length < 12 || f[0].equals("round")) {
                continue;
            }
            runs.add(new Run(Integer.parseInt(f[0]), f[1], f[2], d(f[3]), d(f[4]), d(f[5]), d(f[6]), d(f[7]), (int) d(f[8]), d(f[9]),
                             d(f[10]), f[11].equals("yes")));
        }
        return runs;
    }

    private static double d(String s) {
        return s.isEmpty() ? 0 : Double.parseDouble(s);
    }

    private static List<Run> select(List<Run> runs, String workload, String mode) {
        return runs.stream().filter(r -> r.workload.equals(workload) && r.mode.equals(mode)).toList();
    }

    private static Run one(List<Run> runs, int round, String workload, String mode) {
        return select(runs, workload, mode).stream().filter(r -> r.round == round).findFirst()
            .orElseThrow(() -> new IllegalArgumentException("no " + workload + " " + mode + " run in round " + round));
    }

    private static String name(String mode) {
        return switch (mode) {
            case "jvm" -> "one JVM, 2 threads";
            case "local" -> "Spark local[2]";
            default -> "two-worker cluster";
        };
    }

    private static String label(String workload) {
        return workload.equals("turntable") ? "120-frame turntable 480x360, 4 spp" : "still 960x640, 64 spp, Gaussian";
    }

    private static double mean(double[] v) {
        double s = 0;
        for (double x : v) {
            s += x;
        }
        return v.length == 0 ? 0 : s / v.length;
    }

    private static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double x : v) {
            m = Math.min(m, x);
        }
        return m;
    }

    private static double max(double[] v) {
        double m = Double.NEGATIVE_INFINITY;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }
}

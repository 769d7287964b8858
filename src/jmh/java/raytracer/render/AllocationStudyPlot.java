package raytracer.render;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.apache.commons.math3.distribution.TDistribution;
import org.yaml.snakeyaml.Yaml;
import raytracer.image.chart.Bar;
import raytracer.image.chart.BarChart;

/**
 * The allocation study's plot and table (docs/performance.md), from the JSON files JMH wrote for
 * {@link AllocationStudyBenchmark} ({@code -rf json -rff FILE}). The files may hold the same
 * configuration (workload, threads, JVM, collector, mode) more than once, one round each
 * (tools/studies/allocation-study/run): its iterations are pooled, and the error recomputed over all of them as
 * JMH computes it for one file, the half-width of the 99.9% confidence interval of the mean
 * (Student's t). Draws grouped bars of throughput with that error, one panel per workload, and
 * prints a Markdown table of throughput, allocation and collection, and the speed-ups of reuse
 * over the other modes.
 *
 * <pre>java -cp ... raytracer.render.AllocationStudyPlot RESULTS_FOLDER OUT.png</pre>
 */
public final class AllocationStudyPlot {
    private static final List<String> MODES = List.of("reuse", "fresh", "immutable");

    private AllocationStudyPlot() {
    }

    /** One configuration measured in one file: what ran where, and what JMH measured. */
    record Run(String workload, int threads, String jvm, String gc, String mode, List<Double> iterations, String unit,
               double bytesPerOp, double allocationRate, double gcCount, double gcMillis, double seconds) {

        String key() {
            return workload + "|" + threads + "|" + jvm + "|" + gc + "|" + mode;
        }
    }

    /** A configuration over all its runs. */
    record Result(String workload, int threads, String jvm, String gc, String mode, int forks, int iterations,
                  double score, double error, String unit, double bytesPerOp, double allocationRate,
                  double gcPerSecond, double gcPercent) {

        String category() {
            return jvm + " " + gc + ", " + threads + (threads == 1 ? " thread" : " threads");
        }
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: AllocationStudyPlot RESULTS_FOLDER OUT.png  (the folder holds JMH's JSON files)");
            System.exit(2);
        }
        List<Run> runs = new ArrayList<>();
        try (Stream<Path> files = Files.list(Path.of(args[0]))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".json")).sorted().toList()) {
                runs.addAll(read(file));
            }
        }
        if (runs.isEmpty()) {
            System.err.println("no AllocationStudyBenchmark results in " + args[0]);
            System.exit(1);
        }
        List<Result> results = merge(runs);
        results.sort(Comparator.comparing(Result::workload).reversed().thenComparing(Result::threads)
                         .thenComparing(Result::jvm).thenComparing(Result::gc)
                         .thenComparing(r -> MODES.indexOf(r.mode())));
        writePlot(results, Path.of(args[1]));
        System.out.print(table(results));
        System.out.print(speedUps(results));
    }

    /** The study's runs in one JSON file of JMH's. */
    static List<Run> read(Path file) throws IOException {
        List<Run> runs = new ArrayList<>();
        Object root = new Yaml().load(Files.readString(file)); // JSON is YAML
        if (!(root instanceof List<?> list)) {
            throw new IOException(file + ": not a JSON array of JMH results");
        }
        for (Object item : list) {
            Map<?, ?> r = (Map<?, ?>) item;
            String benchmark = (String) r.get("benchmark");
            if (!benchmark.contains("AllocationStudyBenchmark.")) {
                continue;
            }
            String method = benchmark.substring(benchmark.lastIndexOf('.') + 1);
            Map<?, ?> params = (Map<?, ?>) r.get("params");
            Map<?, ?> primary = (Map<?, ?>) r.get("primaryMetric");
            Map<?, ?> secondary = (Map<?, ?>) r.get("secondaryMetrics");
            boolean frame = method.equals("frame");
            int threads = frame ? Integer.parseInt((String) params.get("threads")) : ((Number) r.get("threads")).intValue();
            List<Double> iterations = new ArrayList<>();
            for (Object fork : (List<?>) primary.get("rawData")) {
                for (Object score : (List<?>) fork) {
                    iterations.add(number(score));
                }
            }
            double seconds = iterations.size() * seconds((String) r.get("measurementTime"));
            runs.add(new Run(frame ? "frame" : "pixel", threads, "JDK " + major((String) r.get("jdkVersion")),
                             collector((List<?>) r.get("jvmArgs")), (String) params.get("mode"), iterations,
                             (String) primary.get("scoreUnit"), iterationMean(secondary, "gc.alloc.rate.norm"),
                             iterationMean(secondary, "gc.alloc.rate"), metric(secondary, "gc.count"),
                             metric(secondary, "gc.time"), seconds));
        }
        return runs;
    }

    /** JMH's iteration time, "2 s" or "500 ms", in seconds. */
    private static double seconds(String time) {
        String[] parts = time.trim().split(" ");
        double value = Double.parseDouble(parts[0]);
        return switch (parts[1]) {
            case "s" -> value;
            case "ms" -> value / 1e3;
            case "us" -> value / 1e6;
            default -> throw new IllegalArgumentException("unknown time unit in '" + time + "'");
        };
    }

    /**
     * Each configuration's runs pooled: the mean of all iterations and the half-width of its 99.9%
     * confidence interval, t(0.9995, n - 1) s / sqrt(n), as JMH gives for one run; bytes per
     * operation and allocation rate averaged over the runs; collections per second and the share
     * of the measured time spent in collections, over all measured iterations.
     */
    static List<Result> merge(List<Run> runs) {
        Map<String, List<Run>> byKey = new java.util.LinkedHashMap<>();
        for (Run run : runs) {
            byKey.computeIfAbsent(run.key(), k -> new ArrayList<>()).add(run);
        }
        List<Result> results = new ArrayList<>();
        for (List<Run> same : byKey.values()) {
            Run first = same.get(0);
            List<Double> all = new ArrayList<>();
            double bytes = 0;
            double rate = 0;
            double count = 0;
            double millis = 0;
            double seconds = 0;
            for (Run run : same) {
                all.addAll(run.iterations());
                bytes += run.bytesPerOp() / same.size();
                rate += run.allocationRate() / same.size();
                count += run.gcCount();
                millis += run.gcMillis();
                seconds += run.seconds();
            }
            int n = all.size();
            double mean = all.stream().mapToDouble(Double::doubleValue).sum() / n;
            double squares = all.stream().mapToDouble(x -> (x - mean) * (x - mean)).sum();
            double error = n < 2 ? Double.NaN
                : new TDistribution(n - 1).inverseCumulativeProbability(0.9995) * Math.sqrt(squares / (n - 1)) / Math.sqrt(n);
            results.add(new Result(first.workload(), first.threads(), first.jvm(), first.gc(), first.mode(), same.size(), n,
                                   mean, error, first.unit(), bytes, rate, count / seconds, 100 * millis / (1000 * seconds)));
        }
        return results;
    }

    private static String major(String version) {
        int dot = version.indexOf('.');
        return dot < 0 ? version : version.substring(0, dot);
    }

    /**
     * The collector a -XX:+Use...GC flag chose (without one, both JDKs pick G1 on a machine of 2
     * CPUs), and "no EA" when escape analysis was turned off.
     */
    private static String collector(List<?> jvmArgs) {
        String gc = "G1";
        String analysis = "";
        for (Object arg : jvmArgs) {
            String a = arg.toString();
            if (a.startsWith("-XX:+Use") && a.endsWith("GC")) {
                gc = a.substring("-XX:+Use".length(), a.length() - 2);
            } else if (a.equals("-XX:-DoEscapeAnalysis")) {
                analysis = " no EA";
            }
        }
        return gc + analysis;
    }

    /** A number of JMH's JSON, where a missing error is written "NaN". */
    private static double number(Object value) {
        if (value instanceof Number n) {
            return n.doubleValue();
        }
        return Double.parseDouble(String.valueOf(value));
    }

    /**
     * The mean of a rate's recorded iterations. JMH's own score divides by the iterations of the
     * primary metric, so an iteration in which the GC profiler recorded nothing counts as 0 there.
     */
    private static double iterationMean(Map<?, ?> secondary, String name) {
        Object m = secondary == null ? null : secondary.get(name);
        if (m == null) {
            return 0;
        }
        double sum = 0;
        int n = 0;
        for (Object fork : (List<?>) ((Map<?, ?>) m).get("rawData")) {
            for (Object value : (List<?>) fork) {
                sum += number(value);
                n++;
            }
        }
        return n == 0 ? number(((Map<?, ?>) m).get("score")) : sum / n;
    }

    private static double metric(Map<?, ?> secondary, String name) {
        Object m = secondary == null ? null : secondary.get(name);
        return m == null ? 0 : number(((Map<?, ?>) m).get("score"));
    }

    /** One panel per workload, stacked, each with its own scale. */
    static void writePlot(List<Result> results, Path png) throws IOException {
        int width = 1500;
        int height = 520;
        List<BufferedImage> panels = new ArrayList<>();
        for (String workload : List.of("pixel", "frame")) {
            List<Bar> bars = new ArrayList<>();
            String unit = "";
            for (Result r : results) {
                if (r.workload().equals(workload)) {
                    bars.add(new Bar(r.mode(), r.category(), r.score(), Double.isFinite(r.error()) ? r.error() : 0));
                    unit = r.unit();
                }
            }
            if (bars.isEmpty()) {
                continue;
            }
            String title = workload.equals("pixel")
                ? "One pixel of the default scene (16 samples, mirrors, shadows): pixels per ms, higher is faster"
                : "The dragon bench frame at 480x270: frames per second, higher is faster";
            panels.add(new BarChart(title, "JVM, collector and threads", unit, bars).draw(width, height));
        }
        BufferedImage image = new BufferedImage(width, height * panels.size(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, image.getWidth(), image.getHeight());
        for (int i = 0; i < panels.size(); i++) {
            g.drawImage(panels.get(i), 0, i * height, null);
        }
        g.dispose();
        Path parent = png.toAbsolutePath().getParent();
        Files.createDirectories(parent);
        Path temporary = Files.createTempFile(parent, ".allocation-study", ".png");
        try {
            ImageIO.write(image, "png", temporary.toFile());
            Files.move(temporary, png, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /** Every result as a Markdown row. */
    static String table(List<Result> results) {
        StringBuilder t = new StringBuilder();
        t.append("| workload | threads | JVM | GC | mode | throughput (99.9% CI, n iterations) | B/op | MB/s allocated | GCs/s | GC time |\n");
        t.append("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
        for (Result r : results) {
            t.append(String.format(Locale.ROOT, "| %s | %d | %s | %s | %s | %s ± %s %s (%d) | %s | %.0f | %.1f | %.1f%% |%n",
                                   r.workload(), r.threads(), r.jvm(), r.gc(), r.mode(), significant(r.score()),
                                   significant(r.error()), r.unit(), r.iterations(),
                                   bytes(r.bytesPerOp()), r.allocationRate(), r.gcPerSecond(), r.gcPercent()));
        }
        return t.toString();
    }

    /**
     * Reuse's throughput over fresh's and immutable's for each workload, threads, JVM and
     * collector; the error of a ratio a / b taken as (a / b) sqrt((ea / a)^2 + (eb / b)^2) from the
     * two confidence half-widths, a first-order estimate.
     */
    static String speedUps(List<Result> results) {
        StringBuilder t = new StringBuilder("\n| workload | threads | JVM | GC | reuse / fresh | reuse / immutable |\n");
        t.append("| --- | --- | --- | --- | --- | --- |\n");
        for (Result reuse : results) {
            if (!reuse.mode().equals("reuse")) {
                continue;
            }
            t.append(String.format(Locale.ROOT, "| %s | %d | %s | %s", reuse.workload(), reuse.threads(), reuse.jvm(), reuse.gc()));
            for (String other : List.of("fresh", "immutable")) {
                Result o = results.stream().filter(r -> r.mode().equals(other) && r.category().equals(reuse.category())
                                                         && r.workload().equals(reuse.workload())).findFirst().orElse(null);
                if (o == null) {
                    t.append(" | -");
                    continue;
                }
                double ratio = reuse.score() / o.score();
                double error = ratio * Math.hypot(reuse.error() / reuse.score(), o.error() / o.score());
                t.append(String.format(Locale.ROOT, " | %.2f ± %.2f", ratio, error));
            }
            t.append(" |\n");
        }
        return t.toString();
    }

    /** Three significant digits, no exponent. */
    private static String significant(double v) {
        if (!Double.isFinite(v)) {
            return "?";
        }
        int digits = v == 0 ? 0 : Math.max(0, 2 - (int) Math.floor(Math.log10(Math.abs(v))));
        return String.format(Locale.ROOT, "%." + digits + "f", v);
    }

    private static String bytes(double b) {
        if (b < 10) {
            return String.format(Locale.ROOT, "%.2f", b);
        }
        if (b < 1e6) {
            return String.format(Locale.ROOT, "%.0f", b);
        }
        return String.format(Locale.ROOT, "%.1f M", b / 1e6);
    }
}

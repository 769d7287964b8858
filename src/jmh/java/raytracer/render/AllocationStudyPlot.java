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
import org.yaml.snakeyaml.Yaml;
import raytracer.image.chart.Bar;
import raytracer.image.chart.BarChart;

/**
 * The allocation study's plot and table (docs/performance.md), from the JSON files JMH wrote for
 * {@link AllocationStudyBenchmark} ({@code -rf json -rff FILE}), one file or more per JVM and
 * collector: grouped bars of throughput with JMH's error (99.9% confidence half-width), one panel
 * per workload, and a Markdown table of throughput, allocation and collection on standard output,
 * with the speed-ups of reuse over the other modes.
 *
 * <pre>java -cp ... raytracer.render.AllocationStudyPlot RESULTS_FOLDER OUT.png</pre>
 */
public final class AllocationStudyPlot {
    private static final List<String> MODES = List.of("reuse", "fresh", "immutable");

    private AllocationStudyPlot() {
    }

    /** One benchmark result: what ran where, and what JMH measured. */
    record Result(String workload, int threads, String jvm, String gc, String mode, double score, double error,
                  String unit, double bytesPerOp, double allocationRate, double gcCount, double gcTime) {

        String category() {
            return jvm + " " + gc + ", " + threads + (threads == 1 ? " thread" : " threads");
        }
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: AllocationStudyPlot RESULTS_FOLDER OUT.png  (the folder holds JMH's JSON files)");
            System.exit(2);
        }
        List<Result> results = new ArrayList<>();
        try (Stream<Path> files = Files.list(Path.of(args[0]))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".json")).sorted().toList()) {
                results.addAll(read(file));
            }
        }
        if (results.isEmpty()) {
            System.err.println("no AllocationStudyBenchmark results in " + args[0]);
            System.exit(1);
        }
        results.sort(Comparator.comparing(Result::workload).reversed().thenComparing(Result::threads)
                         .thenComparing(Result::jvm).thenComparing(Result::gc)
                         .thenComparing(r -> MODES.indexOf(r.mode())));
        writePlot(results, Path.of(args[1]));
        System.out.print(table(results));
        System.out.print(speedUps(results));
    }

    /** The study's results in one JSON file of JMH's. */
    static List<Result> read(Path file) throws IOException {
        List<Result> results = new ArrayList<>();
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
            results.add(new Result(frame ? "frame" : "pixel", threads, "JDK " + major((String) r.get("jdkVersion")),
                                   collector((List<?>) r.get("jvmArgs")), (String) params.get("mode"),
                                   number(primary.get("score")), number(primary.get("scoreError")),
                                   (String) primary.get("scoreUnit"), metric(secondary, "gc.alloc.rate.norm"),
                                   metric(secondary, "gc.alloc.rate"), metric(secondary, "gc.count"),
                                   metric(secondary, "gc.time")));
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
        t.append("| workload | threads | JVM | GC | mode | throughput | B/op | MB/s allocated | GCs | GC ms |\n");
        t.append("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
        for (Result r : results) {
            t.append(String.format(Locale.ROOT, "| %s | %d | %s | %s | %s | %s ± %s %s | %s | %.0f | %.0f | %.0f |%n",
                                   r.workload(), r.threads(), r.jvm(), r.gc(), r.mode(), significant(r.score()),
                                   significant(r.error()), r.unit(), bytes(r.bytesPerOp()), r.allocationRate(),
                                   r.gcCount(), r.gcTime()));
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

package raytracer.render;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.ToDoubleFunction;
import javax.imageio.ImageIO;
import raytracer.image.chart.LogLogChart;
import raytracer.image.chart.Series;

/**
 * The scale study's log-log plot and table (docs/performance.md, "Meshes of tens of millions of
 * triangles"), from the rows tools/studies/scale-study/run appends to its runs.csv: per mesh size and
 * configuration (ours without the cache, writing it, reading it; the old jar; Mitsuba 3) the
 * median of the rounds. Two panels: times (parse, build, render, whole process) and memory (peak
 * heap, largest heap after a collection, peak RSS) against the triangle count, each with a grey
 * guide of linear growth, and 64 and 100 bytes per triangle on the memory panel.
 *
 * <pre>gradle scaleStudyPlot -Presults=RUNS.csv [-Pplot=OUT.png]</pre>
 */
public final class ScaleStudyPlot {
    private static final String[] FIELDS = {"parse_s", "build_s", "read_s", "render_s", "peak_heap_mib", "after_gc_mib",
                                            "rss_mb", "whole_s"};

    private ScaleStudyPlot() {
    }

    /** One run: its mesh, configuration and figures by column name (NaN where absent). */
    record Run(long triangles, String who, String mode, Map<String, Double> figures) {
        String configuration() {
            return who + " " + mode;
        }
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: ScaleStudyPlot RUNS.csv OUT.png");
            System.exit(2);
        }
        List<Run> runs = read(Path.of(args[0]));
        if (runs.isEmpty()) {
            System.err.println("no runs in " + args[0]);
            System.exit(1);
        }
        Map<String, Map<Long, Map<String, Double>>> medians = medians(runs);
        writePlot(medians, Path.of(args[1]));
        System.out.print(table(medians, runs));
    }

    static List<Run> read(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        List<String> header = Arrays.asList(lines.get(0).split(","));
        List<Run> runs = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] cells = line.split(",");
            Map<String, Double> figures = new TreeMap<>();
            for (String field : FIELDS) {
                String cell = cells[header.indexOf(field)];
                figures.put(field, cell.matches("[0-9.]+") ? Double.parseDouble(cell) : Double.NaN);
            }
            runs.add(new Run(Long.parseLong(cells[header.indexOf("triangles")]), cells[header.indexOf("who")],
                             cells[header.indexOf("mode")], figures));
        }
        return runs;
    }

    /** Per configuration and size, the median of each figure over the rounds that have it. */
    static Map<String, Map<Long, Map<String, Double>>> medians(List<Run> runs) {
        Map<String, Map<Long, List<Run>>> grouped = new TreeMap<>();
        for (Run run : runs) {
            grouped.computeIfAbsent(run.configuration(), c -> new TreeMap<>())
                   .computeIfAbsent(run.triangles(), t -> new ArrayList<>()).add(run);
        }
        Map<String, Map<Long, Map<String, Double>>> medians = new TreeMap<>();
        grouped.forEach((configuration, bySize) -> bySize.forEach((size, group) -> {
            Map<String, Double> m = new TreeMap<>();
            for (String field : FIELDS) {
                m.put(field, median(group.stream().mapToDouble(r -> r.figures().get(field)).filter(Double::isFinite).toArray()));
            }
            m.put("rounds", (double) group.size());
            medians.computeIfAbsent(configuration, c -> new TreeMap<>()).put(size, m);
        }));
        return medians;
    }

    private static double median(double[] values) {
        if (values.length == 0) {
            return Double.NaN;
        }
        Arrays.sort(values);
        int n = values.length;
        return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
    }

    private static Series series(Map<String, Map<Long, Map<String, Double>>> medians, String configuration, String field,
                                 String name) {
        Map<Long, Map<String, Double>> bySize = medians.getOrDefault(configuration, Map.of());
        double[] x = bySize.keySet().stream().mapToDouble(Long::doubleValue).toArray();
        double[] y = bySize.values().stream().mapToDouble(m -> m.get(field)).toArray();
        return new Series(name, x, y);
    }

    /** A grey guide through (x0, y0) growing as x^slope, over the sizes measured. */
    private static Series guide(String name, double[] sizes, ToDoubleFunction<Double> y) {
        return new Series(name, sizes, Arrays.stream(sizes).map(s -> y.applyAsDouble(s)).toArray(), true);
    }

    static void writePlot(Map<String, Map<Long, Map<String, Double>>> medians, Path file) throws IOException {
        double[] sizes = medians.values().stream().flatMap(m -> m.keySet().stream()).mapToDouble(Long::doubleValue)
                                .distinct().sorted().toArray();
        double small = sizes[0];
        double wholeAtSmall = medians.get("ours no-cache").get((long) small).get("whole_s");
        List<Series> time = new ArrayList<>(List.of(
            series(medians, "ours no-cache", "parse_s", "OBJ parse"),
            series(medians, "ours no-cache", "build_s", "BVH build (and leaf order)"),
            series(medians, "ours no-cache", "render_s", "render (1080p, 1 spp)"),
            series(medians, "ours no-cache", "whole_s", "whole process, --no-cache"),
            series(medians, "ours cache-read", "whole_s", "whole process, mesh cache read")));
        if (medians.containsKey("mitsuba scalar_rgb")) {
            time.add(series(medians, "mitsuba scalar_rgb", "whole_s", "Mitsuba 3 (scalar_rgb), whole process"));
        }
        time.add(guide("linear in the triangles", sizes, s -> wholeAtSmall * s / small));
        List<Series> memory = new ArrayList<>(List.of(
            series(medians, "ours no-cache", "peak_heap_mib", "peak heap, --no-cache (--stats)"),
            series(medians, "ours no-cache", "after_gc_mib", "largest heap after a collection, --no-cache"),
            series(medians, "ours no-cache", "rss_mb", "peak RSS, --no-cache"),
            series(medians, "ours cache-read", "peak_heap_mib", "peak heap, mesh cache read")));
        if (medians.containsKey("old no-cache")) {
            memory.add(series(medians, "old no-cache", "peak_heap_mib", "peak heap, the old jar"));
        }
        if (medians.containsKey("mitsuba scalar_rgb")) {
            memory.add(series(medians, "mitsuba scalar_rgb", "rss_mb", "Mitsuba 3, peak RSS"));
        }
        memory.add(guide("100 bytes per triangle", sizes, s -> 100 * s / (1 << 20)));
        memory.add(guide("64 bytes per triangle", sizes, s -> 64 * s / (1 << 20)));
        int width = 900;
        int height = 640;
        BufferedImage left = new LogLogChart("Time against mesh size (median of rounds)", "triangles", "seconds", time)
            .draw(width, height);
        BufferedImage right = new LogLogChart("Memory against mesh size", "triangles", "MiB", memory)
            .draw(width, height);
        BufferedImage image = new BufferedImage(2 * width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, image.getWidth(), image.getHeight());
        g.drawImage(left, 0, 0, null);
        g.drawImage(right, width, 0, null);
        g.dispose();
        Path temporary = file.resolveSibling(file.getFileName() + ".partial");
        ImageIO.write(image, "png", temporary.toFile());
        Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING);
    }

    /** The Markdown table of medians: one row per size and configuration. */
    static String table(Map<String, Map<Long, Map<String, Double>>> medians, List<Run> runs) {
        StringBuilder b = new StringBuilder();
        b.append("| triangles | run | rounds | parse | build | cache read | render | peak heap | B/triangle | after a collection "
                 + "| peak RSS | whole process |\n");
        b.append("| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
        for (long size : new TreeSet<>(runs.stream().map(Run::triangles).toList())) {
            for (String configuration : List.of("ours no-cache", "ours cache-write", "ours cache-read", "old no-cache",
                                                "mitsuba scalar_rgb")) {
                Map<String, Double> m = medians.getOrDefault(configuration, Map.of()).get(size);
                if (m == null) {
                    continue;
                }
                double perTriangle = m.get("peak_heap_mib") * (1 << 20) / size;
                b.append(String.format(Locale.ROOT, "| %,d | %s | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s |%n", size,
                    configuration, m.get("rounds"), seconds(m.get("parse_s")), seconds(m.get("build_s")),
                    seconds(m.get("read_s")), seconds(m.get("render_s")), mib(m.get("peak_heap_mib")),
                    Double.isFinite(perTriangle) ? String.format(Locale.ROOT, "%.0f", perTriangle) : "",
                    mib(m.get("after_gc_mib")), Double.isFinite(m.get("rss_mb")) ? String.format(Locale.ROOT, "%,.0f MiB",
                    m.get("rss_mb")) : "", seconds(m.get("whole_s"))));
            }
        }
        return b.toString();
    }

    private static String seconds(double s) {
        return Double.isFinite(s) ? String.format(Locale.ROOT, "%.2f s", s) : "";
    }

    private static String mib(double m) {
        return Double.isFinite(m) ? String.format(Locale.ROOT, "%,.0f MiB", m) : "";
    }
}

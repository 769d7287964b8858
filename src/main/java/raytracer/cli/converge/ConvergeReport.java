package raytracer.cli.converge;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import raytracer.core.Light;
import raytracer.core.World;
import raytracer.image.chart.LogLogChart;
import raytracer.image.chart.Series;

/** The convergence benchmark's results as a table, as CSV, as slopes and as a log-log chart of error against time. */
final class ConvergeReport {
    private static final String[] HEADER = {"configuration", "spp", "light samples", "seconds", "RMSE", "rel. RMSE", "rel. MSE", "worst pixel"};

    private ConvergeReport() {
    }

    /** What the table's reader should know of the reference's own noise (an RMSE; 0 exact, NaN unknown). */
    static String noiseNote(double noise, double referenceMean) {
        if (Double.isNaN(noise)) {
            return ", its own noise unknown";
        }
        if (noise == 0) {
            return "";
        }
        return String.format(Locale.ROOT, ", its own noise RMSE %.4g%s: errors near it are mostly the reference's", noise,
                             referenceMean > 0 ? String.format(Locale.ROOT, " (relative %.4g)", noise / referenceMean) : "");
    }

    /**
     * The area lights' samples per shaded point as the renderer takes them (rounded for the
     * sampler), of the lights the scene has (before the scene analysis leaves any out); "-" without
     * area lights.
     */
    static String lightSamples(World world) {
        TreeSet<Integer> counts = new TreeSet<>();
        for (Light light : world.lightList()) {
            if (light.hasExtent()) {
                counts.add(world.viewPlane().sampler().supportedCount(light.sampleCount()));
            }
        }
        return counts.isEmpty() ? "-" : counts.size() == 1 ? counts.first().toString() : counts.first() + "-" + counts.last();
    }

    /** A text table with a header line, the configuration left-aligned and the figures right-aligned. */
    static String table(List<ConvergeRow> rows) {
        List<String[]> cells = new ArrayList<>();
        cells.add(HEADER);
        for (ConvergeRow r : rows) {
            cells.add(new String[] {r.config(), Integer.toString(r.spp()), r.lightSamples(), format("%.3f", r.seconds()),
                                    format("%.4g", r.error().rmse()), relative(r), format("%.4g", r.error().relativeMse()),
                                    format("%.4g", r.error().worst()) + " at (" + r.error().worstX() + ", " + r.error().worstY() + ")"});
        }
        int[] width = new int[HEADER.length];
        for (String[] line : cells) {
            for (int i = 0; i < line.length; i++) {
                width[i] = Math.max(width[i], line[i].length());
            }
        }
        StringBuilder out = new StringBuilder();
        for (String[] line : cells) {
            for (int i = 0; i < line.length; i++) {
                String pad = " ".repeat(width[i] - line[i].length());
                out.append(i == 0 ? "" : "  ").append(i == 0 ? line[i] + pad : pad + line[i]);
            }
            out.append('\n');
        }
        return out.toString();
    }

    private static String relative(ConvergeRow r) {
        return Double.isNaN(r.error().relativeRmse()) ? "-" : format("%.4g", r.error().relativeRmse());
    }

    private static String format(String pattern, double v) {
        return String.format(Locale.ROOT, pattern, v);
    }

    /** The rows as comma-separated values with a header, full precision, for spreadsheets and scripts. */
    static String csv(List<ConvergeRow> rows) {
        StringBuilder out = new StringBuilder("configuration,spp,light_samples,seconds,rmse,relative_rmse,relative_mse,"
                                              + "worst,worst_x,worst_y,reference_mean\n");
        for (ConvergeRow r : rows) {
            out.append('"').append(r.config().replace("\"", "\"\"")).append('"').append(',').append(r.spp()).append(',')
               .append(r.lightSamples()).append(',').append(r.seconds()).append(',').append(r.error().rmse()).append(',')
               .append(Double.isNaN(r.error().relativeRmse()) ? "" : Double.toString(r.error().relativeRmse())).append(',')
               .append(r.error().relativeMse()).append(',').append(r.error().worst()).append(',').append(r.error().worstX())
               .append(',').append(r.error().worstY()).append(',').append(r.error().referenceMean()).append('\n');
        }
        return out.toString();
    }

    /**
     * Per configuration, the least-squares slope of log(error) against log(seconds) with its
     * standard error ({@link FittedSlope}): -0.5 is the rate of independent random sampling;
     * configurations with fewer than two usable points have none.
     */
    static Map<String, FittedSlope> slopes(List<ConvergeRow> rows) {
        Map<String, FittedSlope> slopes = new LinkedHashMap<>();
        byConfig(rows).forEach((name, list) -> {
            double[][] xy = points(list);
            if (xy[0].length >= 2) {
                slopes.put(name, FittedSlope.of(xy[0], xy[1]));
            }
        });
        return slopes;
    }

    /**
     * The error (relative RMSE; the RMSE when the reference is black) against seconds, one curve
     * per configuration with each point labelled by its samples per pixel, a dashed guide of slope
     * -1/2 through the first curve's first point, and, when {@code referenceNoise} (an RMSE) is
     * positive, a level line at the reference's own noise.
     */
    static LogLogChart chart(String title, List<ConvergeRow> rows, double referenceNoise) {
        List<Series> series = new ArrayList<>();
        double minSeconds = Double.POSITIVE_INFINITY;
        double maxSeconds = 0;
        for (Map.Entry<String, List<ConvergeRow>> entry : byConfig(rows).entrySet()) {
            double[][] xy = points(entry.getValue());
            series.add(new Series(entry.getKey(), xy[0], xy[1], false, sppLabels(entry.getValue())));
            for (double s : xy[0]) {
                minSeconds = Math.min(minSeconds, s);
                maxSeconds = Math.max(maxSeconds, s);
            }
        }
        if (!series.isEmpty() && series.get(0).x().length > 0 && maxSeconds > minSeconds) {
            double x0 = series.get(0).x()[0];
            double y0 = series.get(0).y()[0];
            series.add(new Series("slope -1/2 (independent samples)", new double[] {minSeconds, maxSeconds},
                                  new double[] {y0 * Math.sqrt(x0 / minSeconds), y0 * Math.sqrt(x0 / maxSeconds)}, true));
            if (referenceNoise > 0 && Double.isFinite(referenceNoise)) {
                double level = relative(rows) ? referenceNoise / rows.get(0).error().referenceMean() : referenceNoise;
                series.add(new Series("the reference's own noise", new double[] {minSeconds, maxSeconds},
                                      new double[] {level, level}, true));
            }
        }
        return new LogLogChart(title, "render wall time (s)", yLabel(rows), series);
    }

    private static boolean relative(List<ConvergeRow> rows) {
        return rows.stream().noneMatch(r -> Double.isNaN(r.error().relativeRmse()));
    }

    private static String yLabel(List<ConvergeRow> rows) {
        return relative(rows) ? "relative RMSE (RMSE / mean of the reference)" : "RMSE (linear radiance)";
    }

    private static Map<String, List<ConvergeRow>> byConfig(List<ConvergeRow> rows) {
        Map<String, List<ConvergeRow>> map = new LinkedHashMap<>();
        rows.forEach(r -> map.computeIfAbsent(r.config(), k -> new ArrayList<>()).add(r));
        return map;
    }

    /** "16 spp" for each row that {@link #points} keeps, in its order. */
    private static List<String> sppLabels(List<ConvergeRow> rows) {
        boolean relative = relative(rows);
        List<String> labels = new ArrayList<>();
        for (ConvergeRow r : rows) {
            double error = relative ? r.error().relativeRmse() : r.error().rmse();
            if (r.seconds() > 0 && error > 0) {
                labels.add(r.spp() + " spp");
            }
        }
        return labels;
    }

    /** Seconds and error of the rows whose both are positive, the only ones a log-log plot can place. */
    private static double[][] points(List<ConvergeRow> rows) {
        boolean relative = relative(rows);
        List<double[]> kept = new ArrayList<>();
        for (ConvergeRow r : rows) {
            double error = relative ? r.error().relativeRmse() : r.error().rmse();
            if (r.seconds() > 0 && error > 0) {
                kept.add(new double[] {r.seconds(), error});
            }
        }
        return new double[][] {kept.stream().mapToDouble(p -> p[0]).toArray(), kept.stream().mapToDouble(p -> p[1]).toArray()};
    }
}

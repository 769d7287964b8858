package raytracer.image.chart;

import java.awt.BasicStroke;
import java.awt.Font;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * A line chart with both axes logarithmic over whole decades (see {@link DecadeAxis}), one coloured
 * curve with markers per measured series (and a label at each point when the series has them),
 * guides dashed grey, the legend below. Points whose x or y is not positive cannot be placed on a
 * log axis and are left out.
 */
public record LogLogChart(String title, String xLabel, String yLabel, List<Series> series) {
    private static final float LINE_WIDTH = 2f;
    /** Guides are told apart by their dashes: long, short, long-short. */
    private static final float[][] DASHES = {{8, 5}, {2, 4}, {10, 4, 2, 4}};

    public LogLogChart {
        series = List.copyOf(series);
        Set<String> names = new HashSet<>();
        for (Series s : series) {
            if (!names.add(s.name())) {
                throw new IllegalArgumentException("two series are named '" + s.name() + "'; a legend needs distinct names");
            }
        }
    }

    /** The chart as an image of {@code width} x {@code height} pixels. */
    public BufferedImage draw(int width, int height) {
        return ChartStyle.draw(chart(), width, height);
    }

    /** Writes the chart as a PNG file, through a temporary file. */
    public void writePng(Path file, int width, int height) throws IOException {
        ChartStyle.writePng(draw(width, height), file);
    }

    JFreeChart chart() {
        XYSeriesCollection data = new XYSeriesCollection();
        XYLineAndShapeRenderer renderer = new XYLineAndShapeRenderer(true, true);
        int measured = 0;
        int guides = 0;
        for (int i = 0; i < series.size(); i++) {
            Series s = series.get(i);
            XYSeries points = new XYSeries(s.name(), false, true);
            List<String> labels = new ArrayList<>();
            double[] x = s.x();
            double[] y = s.y();
            for (int j = 0; j < x.length; j++) {
                if (x[j] > 0 && y[j] > 0 && Double.isFinite(x[j]) && Double.isFinite(y[j])) {
                    points.add(x[j], y[j]);
                    if (s.labels() != null) {
                        labels.add(s.labels().get(j));
                    }
                }
            }
            data.addSeries(points);
            if (s.labels() != null) {
                label(renderer, i, labels);
            }
            if (s.guide()) {
                renderer.setSeriesPaint(i, Palette.GUIDE);
                renderer.setSeriesStroke(i, new BasicStroke(LINE_WIDTH, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                                                            DASHES[guides++ % DASHES.length], 0));
                renderer.setSeriesShapesVisible(i, false);
            } else {
                renderer.setSeriesPaint(i, Palette.colour(measured++));
                renderer.setSeriesStroke(i, new BasicStroke(LINE_WIDTH));
            }
        }
        DecadeAxis xAxis = axis(xLabel, values(true));
        DecadeAxis yAxis = axis(yLabel, values(false));
        XYPlot plot = new XYPlot(data, xAxis, yAxis, renderer);
        plot.setDomainGridlinePaint(ChartStyle.GRID);
        plot.setRangeGridlinePaint(ChartStyle.GRID);
        plot.setDomainGridlineStroke(ChartStyle.GRID_STROKE);
        plot.setRangeGridlineStroke(ChartStyle.GRID_STROKE);
        plot.setDomainMinorGridlinesVisible(true);
        plot.setRangeMinorGridlinesVisible(true);
        plot.setDomainMinorGridlinePaint(ChartStyle.GRID);
        plot.setRangeMinorGridlinePaint(ChartStyle.GRID);
        plot.setDomainMinorGridlineStroke(ChartStyle.MINOR_GRID_STROKE);
        plot.setRangeMinorGridlineStroke(ChartStyle.MINOR_GRID_STROKE);
        return ChartStyle.chart(title, plot);
    }

    /** Writes labels.get(j) above point j of series {@code index}, in the axes' font. */
    private static void label(XYLineAndShapeRenderer renderer, int index, List<String> labels) {
        renderer.setSeriesItemLabelGenerator(index, (dataset, series, item) -> labels.get(item));
        renderer.setSeriesItemLabelsVisible(index, true);
        renderer.setSeriesItemLabelFont(index, new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        renderer.setSeriesItemLabelPaint(index, ChartStyle.LABEL);
    }

    private static DecadeAxis axis(String label, double[] values) {
        DecadeAxis axis = new DecadeAxis(label);
        axis.setLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        axis.setTickLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        double[] range = DecadeAxis.decades(values);
        axis.setRange(range[0], range[1]);
        return axis;
    }

    /** Every x (or y) value of the points that can be drawn. */
    private double[] values(boolean x) {
        return series.stream()
            .flatMapToDouble(s -> {
                double[] xs = s.x();
                double[] ys = s.y();
                return java.util.stream.IntStream.range(0, xs.length)
                    .filter(j -> xs[j] > 0 && ys[j] > 0 && Double.isFinite(xs[j]) && Double.isFinite(ys[j]))
                    .mapToDouble(j -> x ? xs[j] : ys[j]);
            })
            .toArray();
    }
}

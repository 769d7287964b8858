package raytracer.image.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.chart.renderer.category.StatisticalBarRenderer;
import org.jfree.data.statistics.DefaultStatisticalCategoryDataset;

/**
 * Bars grouped by category, one colour per series, each with an error bar of plus or minus its
 * error (a confidence half-width, say); the value axis starts at 0, the legend is below.
 */
public record BarChart(String title, String categoryLabel, String valueLabel, List<Bar> bars) {

    public BarChart {
        bars = List.copyOf(bars);
        Set<String> seen = new HashSet<>();
        for (Bar b : bars) {
            if (!seen.add(b.series() + "\u0000" + b.category())) {
                throw new IllegalArgumentException("two bars of series '" + b.series() + "' in category '" + b.category() + "'");
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

    /** Series and categories in the order they first appear. */
    DefaultStatisticalCategoryDataset dataset() {
        DefaultStatisticalCategoryDataset data = new DefaultStatisticalCategoryDataset();
        Set<String> series = new LinkedHashSet<>();
        Set<String> categories = new LinkedHashSet<>();
        bars.forEach(b -> {
            series.add(b.series());
            categories.add(b.category());
        });
        // registering the keys in order first keeps the first-seen order whatever the bars' order
        for (String s : series) {
            for (String c : categories) {
                data.add(null, null, s, c);
            }
        }
        bars.forEach(b -> data.add(b.value(), b.error(), b.series(), b.category()));
        return data;
    }

    JFreeChart chart() {
        DefaultStatisticalCategoryDataset data = dataset();
        StatisticalBarRenderer renderer = new StatisticalBarRenderer();
        renderer.setBarPainter(new StandardBarPainter());
        renderer.setShadowVisible(false);
        renderer.setDrawBarOutline(false);
        renderer.setItemMargin(0.05);
        renderer.setErrorIndicatorPaint(Color.BLACK);
        renderer.setErrorIndicatorStroke(new BasicStroke(1.5f));
        for (int i = 0; i < data.getRowCount(); i++) {
            renderer.setSeriesPaint(i, Palette.colour(i));
        }
        CategoryAxis categories = new CategoryAxis(categoryLabel);
        categories.setLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        categories.setTickLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        // "JDK 17 G1 no EA, 2 threads" takes three lines under a narrow group of bars
        categories.setMaximumCategoryLabelLines(3);
        NumberAxis values = new NumberAxis(valueLabel);
        values.setLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        values.setTickLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        values.setAutoRangeIncludesZero(true);
        CategoryPlot plot = new CategoryPlot(data, categories, values, renderer);
        plot.setRangeGridlinePaint(ChartStyle.GRID);
        plot.setRangeGridlineStroke(ChartStyle.GRID_STROKE);
        return ChartStyle.chart(title, plot);
    }
}

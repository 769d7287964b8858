package raytracer.image.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.IntStream;
import javax.imageio.ImageIO;
import org.jfree.chart.axis.NumberTick;
import org.jfree.chart.axis.TickType;
import org.jfree.chart.labels.XYItemLabelGenerator;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYItemRenderer;
import org.jfree.chart.ui.RectangleEdge;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The charts drawn to PNG: the right size, not blank, each series in its colour inside the plot,
 * decade ticks on log axes, error bars that show. With RAYTRACER_CHART_DIR=DIR in the environment the
 * images are kept there to look at.
 */
class ChartTest {
    @TempDir
    Path dir;

    private Path out(String name) {
        String keep = System.getenv("RAYTRACER_CHART_DIR");
        return keep != null ? Path.of(keep, name) : dir.resolve(name);
    }

    /** Pixels of exactly {@code colour} in the middle 80% of the image (where the plot area lies). */
    private static long count(BufferedImage image, Color colour) {
        int w = image.getWidth();
        int h = image.getHeight();
        return IntStream.range(0, w * h)
            .filter(i -> i % w > w / 10 && i % w < w * 9 / 10 && i / w > h / 10 && i / w < h * 9 / 10)
            .filter(i -> (image.getRGB(i % w, i / w) & 0xffffff) == (colour.getRGB() & 0xffffff))
            .count();
    }

    /** Pixels darker than 64 in every channel in the middle 80% of the image. */
    private static long dark(BufferedImage image) {
        int w = image.getWidth();
        int h = image.getHeight();
        return IntStream.range(0, w * h)
            .filter(i -> i % w > w / 10 && i % w < w * 9 / 10 && i / w > h / 10 && i / w < h * 9 / 10)
            .map(i -> image.getRGB(i % w, i / w))
            .filter(rgb -> (rgb >> 16 & 0xff) < 64 && (rgb >> 8 & 0xff) < 64 && (rgb & 0xff) < 64)
            .count();
    }

    private static LogLogChart convergence() {
        double[] seconds = {0.05, 0.2, 0.8, 3.2};
        return new LogLogChart("error against time", "render time (s)", "relative RMSE", List.of(
            new Series("random", seconds, new double[] {0.3, 0.15, 0.075, 0.0375}),
            new Series("multi-jittered", seconds, new double[] {0.1, 0.03, 0.009, 0.0027}),
            new Series("slope -1/2", new double[] {0.05, 3.2}, new double[] {0.1, 0.0125}, true)));
    }

    @Test
    void logLogChartShowsEverySeriesInItsColour() throws IOException {
        Path png = out("loglog.png");
        convergence().writePng(png, 640, 480);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(640, image.getWidth());
        assertEquals(480, image.getHeight());
        long distinct = IntStream.range(0, 640 * 480).map(i -> image.getRGB(i % 640, i / 640)).distinct().count();
        assertTrue(distinct > 30, "a blank or nearly blank chart: " + distinct + " colours");
        assertTrue(count(image, Palette.colour(0)) > 300, "first series missing: " + count(image, Palette.colour(0)));
        assertTrue(count(image, Palette.colour(1)) > 300, "second series missing: " + count(image, Palette.colour(1)));
        assertTrue(count(image, Palette.GUIDE) > 50, "guide line missing: " + count(image, Palette.GUIDE));
        // the guide takes no colour of its own: there is no third measured colour
        assertEquals(0, count(image, Palette.colour(2)));
    }

    @Test
    void axesSpanWholeDecadesWithATickAtEachPowerOfTen() {
        assertArrayEquals(new double[] {0.01, 1}, DecadeAxis.decades(new double[] {0.027, 0.3, -1, 0}));
        assertArrayEquals(new double[] {0.01, 10}, DecadeAxis.decades(new double[] {0.05, 3.2}));
        assertArrayEquals(new double[] {1, 10}, DecadeAxis.decades(new double[] {1}));
        assertArrayEquals(new double[] {1, 10}, DecadeAxis.decades(new double[] {0, Double.NaN}));
        DecadeAxis axis = new DecadeAxis("t");
        axis.setRange(0.01, 10);
        List<NumberTick> ticks = axis.ticks(RectangleEdge.BOTTOM);
        List<String> majors = ticks.stream().filter(t -> t.getTickType() == TickType.MAJOR).map(NumberTick::getText).toList();
        assertEquals(List.of("0.01", "0.1", "1", "10"), majors);
        // 2..9 in each of the three decades
        assertEquals(24, ticks.stream().filter(t -> t.getTickType() == TickType.MINOR).count());
        assertEquals(0.2, ticks.stream().filter(t -> t.getTickType() == TickType.MINOR).skip(8).findFirst().get().getValue(), 1e-12);
        assertEquals("1e-5", DecadeAxis.label(-5));
        assertEquals("0.0001", DecadeAxis.label(-4));
        assertEquals("10000", DecadeAxis.label(4));
        assertEquals("1e6", DecadeAxis.label(6));
    }

    private static void assertArrayEquals(double[] expected, double[] actual) {
        org.junit.jupiter.api.Assertions.assertArrayEquals(expected, actual, 1e-12);
    }

    @Test
    void pointsThatALogAxisCannotShowAreLeftOut() {
        LogLogChart chart = new LogLogChart("t", "x", "y", List.of(
            new Series("a", new double[] {1, 2, 0, 4}, new double[] {1, 0, 3, 4})));
        assertEquals(2, chart.chart().getXYPlot().getDataset().getItemCount(0));
        BufferedImage image = chart.draw(300, 200);
        assertTrue(count(image, Palette.colour(0)) > 20);
    }

    @Test
    void pointsCarryTheirLabelsAndALeftOutPointTakesItsLabelAlong() {
        LogLogChart chart = new LogLogChart("t", "x", "y", List.of(
            new Series("a", new double[] {1, 2, 0, 4}, new double[] {1, 2, 3, 4}, false, List.of("1 spp", "4 spp", "16 spp", "64 spp")),
            new Series("b", new double[] {1, 4}, new double[] {2, 3})));
        XYPlot plot = chart.chart().getXYPlot();
        XYItemRenderer renderer = plot.getRenderer();
        XYItemLabelGenerator labels = renderer.getSeriesItemLabelGenerator(0);
        assertTrue(renderer.isSeriesItemLabelsVisible(0));
        assertEquals(List.of("1 spp", "4 spp", "64 spp"), List.of(labels.generateLabel(plot.getDataset(), 0, 0),
                                                                  labels.generateLabel(plot.getDataset(), 0, 1),
                                                                  labels.generateLabel(plot.getDataset(), 0, 2)),
                     "the point at x = 0 cannot be drawn: its label goes with it");
        assertFalse(renderer.isSeriesItemLabelsVisible(1), "a series without labels shows none");
        // drawn, the labels add dark grey text beside the points
        assertTrue(count(chart.draw(400, 300), ChartStyle.LABEL) > 20, "no label text drawn");
        assertThrows(IllegalArgumentException.class, () -> new Series("c", new double[] {1, 2}, new double[] {1, 2}, false, List.of("x")));
    }

    @Test
    void seriesNamesMustDiffer() {
        Series a = new Series("a", new double[] {1}, new double[] {1});
        assertThrows(IllegalArgumentException.class, () -> new LogLogChart("t", "x", "y", List.of(a, a)));
        assertThrows(IllegalArgumentException.class, () -> new Series("b", new double[] {1, 2}, new double[] {1}));
    }

    private static BarChart bars(double error) {
        return new BarChart("time per pixel", "workload", "ns per pixel", List.of(
            new Bar("reuse", "default, 1 thread", 100, error), new Bar("fresh", "default, 1 thread", 140, error),
            new Bar("reuse", "dragon, 2 threads", 60, error), new Bar("fresh", "dragon, 2 threads", 95, error),
            new Bar("immutable", "dragon, 2 threads", 120, error)));
    }

    @Test
    void barChartShowsEachSeriesInItsColourWithErrorBars() throws IOException {
        Path png = out("bars.png");
        bars(12).writePng(png, 640, 480);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(640, image.getWidth());
        for (int i = 0; i < 3; i++) {
            assertTrue(count(image, Palette.colour(i)) > 1000, "series " + i + " missing: " + count(image, Palette.colour(i)));
        }
        // the error bars are black strokes over and above the bars: more dark pixels with them than without
        long withErrors = dark(image);
        long without = dark(bars(0).draw(640, 480));
        assertTrue(withErrors > without + 100, "error bars do not show: " + withErrors + " against " + without);
    }

    @Test
    void barChartKeepsSeriesAndCategoriesInTheOrderTheyCome() {
        var data = bars(5).dataset();
        assertEquals(List.of("reuse", "fresh", "immutable"), data.getRowKeys());
        assertEquals(List.of("default, 1 thread", "dragon, 2 threads"), data.getColumnKeys());
        assertEquals(95.0, data.getMeanValue("fresh", "dragon, 2 threads").doubleValue(), 0);
        assertEquals(5.0, data.getStdDevValue("fresh", "dragon, 2 threads").doubleValue(), 0);
        assertEquals(null, data.getMeanValue("immutable", "default, 1 thread"));
        assertThrows(IllegalArgumentException.class, () -> new Bar("a", "b", 1, -1));
        assertThrows(IllegalArgumentException.class,
            () -> new BarChart("t", "c", "v", List.of(new Bar("a", "b", 1, 0), new Bar("a", "b", 2, 0))));
        assertTrue(Files.notExists(dir.resolve("nothing")));
    }
}

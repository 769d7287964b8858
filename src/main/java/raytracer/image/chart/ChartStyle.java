package raytracer.image.chart;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.Plot;
import org.jfree.chart.title.LegendTitle;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.RectangleInsets;
import raytracer.image.AtomicFile;

/** What both charts share: a white page, grey grid lines, the legend below, PNG output through a temporary file. */
final class ChartStyle {
    static final Color GRID = new Color(0xD0D0D0);
    /** The labels written beside points: dark grey, readable over any curve's colour. */
    static final Color LABEL = new Color(0x404040);
    static final BasicStroke GRID_STROKE = new BasicStroke(0.8f);
    static final BasicStroke MINOR_GRID_STROKE = new BasicStroke(0.5f);

    private ChartStyle() {
    }

    static JFreeChart chart(String title, Plot plot) {
        JFreeChart chart = new JFreeChart(title, new Font(Font.SANS_SERIF, Font.BOLD, 15), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        // room on the right for the last tick label, which is centred on the plot's edge
        chart.setPadding(new RectangleInsets(8, 8, 8, 24));
        plot.setBackgroundPaint(Color.WHITE);
        LegendTitle legend = chart.getLegend();
        legend.setPosition(RectangleEdge.BOTTOM);
        legend.setItemFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        return chart;
    }

    static BufferedImage draw(JFreeChart chart, int width, int height) {
        if (width < 100 || height < 100) {
            throw new IllegalArgumentException("a chart needs at least 100 x 100 pixels, got " + width + " x " + height);
        }
        return chart.createBufferedImage(width, height, BufferedImage.TYPE_INT_RGB, null);
    }

    static void writePng(BufferedImage image, Path file) throws IOException {
        AtomicFile.write(file, out -> {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("no PNG encoder available");
            }
        });
    }
}

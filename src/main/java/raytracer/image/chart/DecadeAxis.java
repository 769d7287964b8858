package raytracer.image.chart;

import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import org.jfree.chart.axis.AxisState;
import org.jfree.chart.axis.LogAxis;
import org.jfree.chart.axis.NumberTick;
import org.jfree.chart.axis.TickType;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.TextAnchor;

/**
 * A base-10 logarithmic axis over whole decades: a labelled tick at every power of ten and
 * unlabelled minor ticks at 2, 3, ... 9 times it, as on log-log graph paper.
 */
final class DecadeAxis extends LogAxis {
    private static final long serialVersionUID = 1L;

    DecadeAxis(String label) {
        super(label);
        setBase(10);
        setMinorTickMarksVisible(true);
    }

    /**
     * The whole decades around the positive values in {@code data}: [10^floor(log10 min),
     * 10^ceil(log10 max)], at least one decade wide; [1, 10] when there is no positive value.
     */
    static double[] decades(double[] data) {
        double min = Double.POSITIVE_INFINITY;
        double max = 0;
        for (double v : data) {
            if (v > 0 && Double.isFinite(v)) {
                min = Math.min(min, v);
                max = Math.max(max, v);
            }
        }
        if (max == 0) {
            return new double[] {1, 10};
        }
        int low = (int) Math.floor(Math.log10(min) + 1e-12);
        int high = (int) Math.ceil(Math.log10(max) - 1e-12);
        if (high <= low) {
            high = low + 1;
        }
        return new double[] {Math.pow(10, low), Math.pow(10, high)};
    }

    /** A power of ten as people write it: 0.001 to 10000 in full, beyond that 1e-5, 1e6. */
    static String label(int exponent) {
        if (exponent < -4 || exponent > 4) {
            return "1e" + exponent;
        }
        return new BigDecimal(BigDecimal.ONE.scaleByPowerOfTen(exponent).toPlainString()).stripTrailingZeros().toPlainString();
    }

    /** The ticks of the current range: majors at the powers of ten, minors between. */
    List<NumberTick> ticks(RectangleEdge edge) {
        boolean vertical = RectangleEdge.isLeftOrRight(edge);
        TextAnchor anchor = vertical ? (edge == RectangleEdge.LEFT ? TextAnchor.CENTER_RIGHT : TextAnchor.CENTER_LEFT)
                                     : (edge == RectangleEdge.TOP ? TextAnchor.BOTTOM_CENTER : TextAnchor.TOP_CENTER);
        double lower = getLowerBound();
        double upper = getUpperBound();
        List<NumberTick> ticks = new ArrayList<>();
        int first = (int) Math.floor(Math.log10(lower) + 1e-9);
        int last = (int) Math.ceil(Math.log10(upper) - 1e-9);
        for (int e = first; e <= last; e++) {
            double decade = Math.pow(10, e);
            for (int k = 1; k <= 9; k++) {
                double v = k * decade;
                if (v < lower * (1 - 1e-9) || v > upper * (1 + 1e-9)) {
                    continue;
                }
                ticks.add(k == 1 ? new NumberTick(TickType.MAJOR, v, label(e), anchor, anchor, 0)
                                 : new NumberTick(TickType.MINOR, v, "", anchor, anchor, 0));
            }
        }
        return ticks;
    }

    @Override
    public List<NumberTick> refreshTicks(Graphics2D g2, AxisState state, Rectangle2D dataArea, RectangleEdge edge) {
        return ticks(edge);
    }
}

package raytracer.image.chart;

import java.util.List;

/**
 * One curve of a line chart: the points (x[i], y[i]) joined in the given order, with a marker at
 * each and, when {@code labels} is not null, labels[i] written beside point i; a {@code guide} (a
 * slope to compare with, say) is drawn as a grey dashed line without markers.
 */
public record Series(String name, double[] x, double[] y, boolean guide, List<String> labels) {

    public Series {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a series needs a name");
        }
        if (x.length != y.length) {
            throw new IllegalArgumentException("series '" + name + "' has " + x.length + " x values but " + y.length + " y values");
        }
        if (labels != null && labels.size() != x.length) {
            throw new IllegalArgumentException("series '" + name + "' has " + x.length + " points but " + labels.size() + " labels");
        }
        x = x.clone();
        y = y.clone();
        labels = labels == null ? null : List.copyOf(labels);
    }

    /** A curve without labels: measured (drawn in colour with markers) or a guide. */
    public Series(String name, double[] x, double[] y, boolean guide) {
        this(name, x, y, guide, null);
    }

    /** A measured curve, drawn in colour with markers. */
    public Series(String name, double[] x, double[] y) {
        this(name, x, y, false);
    }

    @Override
    public double[] x() {
        return x.clone();
    }

    @Override
    public double[] y() {
        return y.clone();
    }
}

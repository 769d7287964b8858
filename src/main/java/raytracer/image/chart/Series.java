package raytracer.image.chart;

/**
 * One curve of a line chart: the points (x[i], y[i]) joined in the given order, with a marker at
 * each; a {@code guide} (a slope to compare with, say) is drawn as a grey dashed line without markers.
 */
public record Series(String name, double[] x, double[] y, boolean guide) {

    public Series {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a series needs a name");
        }
        if (x.length != y.length) {
            throw new IllegalArgumentException("series '" + name + "' has " + x.length + " x values but " + y.length + " y values");
        }
        x = x.clone();
        y = y.clone();
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

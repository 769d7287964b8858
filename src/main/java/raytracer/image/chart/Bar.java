package raytracer.image.chart;

/** One bar of a grouped bar chart: the {@code value} of {@code series} in {@code category}, plus or minus {@code error}. */
public record Bar(String series, String category, double value, double error) {

    public Bar {
        if (series == null || category == null) {
            throw new IllegalArgumentException("a bar needs a series and a category");
        }
        if (!Double.isFinite(value) || !(error >= 0) || !Double.isFinite(error)) {
            throw new IllegalArgumentException("bar '" + series + "' in '" + category + "' needs a finite value and a finite error"
                                               + " of at least 0, got " + value + " +- " + error);
        }
    }
}

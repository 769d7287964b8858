package raytracer.image;

/**
 * How far an image is from a reference, over all pixels and all three channels of linear radiance
 * (n = 3 x width x height values x_i of the image, r_i of the reference):
 * <ul>
 * <li>{@code rmse} = sqrt(sum (x_i - r_i)^2 / n);</li>
 * <li>{@code relativeRmse} = rmse / mean(r_i), NaN when the reference is black;</li>
 * <li>{@code relativeMse} = sum ((x_i - r_i)^2 / (r_i^2 + 0.01)) / n, pbrt's relative MSE: the 0.01
 *     ({@link #RELATIVE_MSE_EPSILON}) keeps black pixels from dividing by zero;</li>
 * <li>{@code worst} = the largest |x_i - r_i|, at pixel ({@code worstX}, {@code worstY}) counted
 *     from the top left, the first such pixel in row order.</li>
 * </ul>
 * The image's values are multiplied by a scale first (the scene's exposure, so a film compares
 * with the .pfm files the renderer writes). {@link #compareDisplayed} compares the values a display
 * gets instead: both images clamped to [0, 1] and sRGB-encoded (without rounding to 8 bits), as PNG
 * files hold them, where an error in the shadows weighs more than the same error in the lights.
 */
public record ErrorMetrics(double rmse, double relativeRmse, double relativeMse, double worst, int worstX, int worstY,
                           double referenceMean) {
    public static final double RELATIVE_MSE_EPSILON = 0.01;

    /** Compares {@code image} (times {@code scale}) with {@code reference}, which must be as large. */
    public static ErrorMetrics compare(Film image, double scale, Film reference) {
        return compare(image, scale, reference, false);
    }

    /** As {@link #compare}, on the sRGB-encoded values of both images clamped to [0, 1]. */
    public static ErrorMetrics compareDisplayed(Film image, double scale, Film reference) {
        return compare(image, scale, reference, true);
    }

    private static double displayed(double linear) {
        return ToneMap.srgbEncode(Math.min(1, Math.max(0, linear)));
    }

    private static ErrorMetrics compare(Film image, double scale, Film reference, boolean srgb) {
        if (image.width() != reference.width() || image.height() != reference.height()) {
            throw new IllegalArgumentException("the image is " + image.width() + "x" + image.height()
                                               + " but the reference is " + reference.width() + "x" + reference.height());
        }
        double squares = 0;
        double relative = 0;
        double referenceSum = 0;
        double worst = -1;
        int worstX = 0;
        int worstY = 0;
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    double r = srgb ? displayed(reference.get(x, y, c)) : reference.get(x, y, c);
                    double v = image.get(x, y, c) * scale;
                    double d = (srgb ? displayed(v) : v) - r;
                    squares += d * d;
                    relative += d * d / (r * r + RELATIVE_MSE_EPSILON);
                    referenceSum += r;
                    if (Math.abs(d) > worst) {
                        worst = Math.abs(d);
                        worstX = x;
                        worstY = y;
                    }
                }
            }
        }
        double n = 3.0 * image.width() * image.height();
        double rmse = Math.sqrt(squares / n);
        double mean = referenceSum / n;
        return new ErrorMetrics(rmse, mean > 0 ? rmse / mean : Double.NaN, relative / n, worst, worstX, worstY, mean);
    }
}

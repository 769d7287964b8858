package raytracer.image;

/**
 * Maps a scalar film (e.g. BVH tests per pixel) to a heat ramp, black - blue - red - yellow - white,
 * so that brighter means more. The ramp runs from the smallest to the largest value in the image.
 */
public final class FalseColor {
    private static final double[][] RAMP = {{0, 0, 0}, {0.05, 0.05, 0.6}, {0.85, 0.1, 0.1}, {1, 0.85, 0.1}, {1, 1, 1}};

    private FalseColor() {
    }

    /** The range of channel 0 over the film: {min, max}. */
    public static double[] range(Film film) {
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                min = Math.min(min, film.get(x, y, 0));
                max = Math.max(max, film.get(x, y, 0));
            }
        }
        return new double[] {min, max};
    }

    /** A new film whose linear colours, once sRGB-encoded, show channel 0 of {@code film} on the ramp. */
    public static Film apply(Film film, double min, double max) {
        Film out = new Film(film.width(), film.height());
        double[] c = new double[3];
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                color(film.get(x, y, 0), min, max, c);
                out.set(x, y, c[0], c[1], c[2]);
            }
        }
        return out;
    }

    /**
     * The linear colour that, once sRGB-encoded, shows {@code value} on the ramp from {@code min} to
     * {@code max}, into {@code rgb[0 .. 3)}: one pixel of {@link #apply}, for a preview that colours
     * tiles as they finish.
     */
    public static void color(double value, double min, double max, double[] rgb) {
        double span = max > min ? max - min : 1;
        double f = Math.max(0, Math.min(1, (value - min) / span));
        double pos = f * (RAMP.length - 1);
        int i = Math.min((int) pos, RAMP.length - 2);
        double w = pos - i;
        for (int k = 0; k < 3; k++) {
            // interpolate in display space, then store linear so the PNG encoder restores it
            double display = (1 - w) * RAMP[i][k] + w * RAMP[i + 1][k];
            rgb[k] = ToneMap.srgbDecode(display);
        }
    }
}

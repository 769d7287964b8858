package raytracer.cli.show;

import raytracer.image.DisplayCodes;
import raytracer.image.FalseColor;
import raytracer.image.Film;

/**
 * The bvh-cost view while it renders: the false-colour ramp over the range of the tiles finished so
 * far, since the image's range, which the file uses, is known only at the end; the window then
 * shows the file's colours ({@link ShowTone#png} of the false-colour film).
 */
final class ShowCostTone implements ShowTone {
    private final DisplayCodes codes = new DisplayCodes(1, true);
    private final double[] rgb = new double[3];
    private double min = Double.POSITIVE_INFINITY;
    private double max = Double.NEGATIVE_INFINITY;

    @Override
    public int rgb(Film film, int x, int y) {
        FalseColor.color(film.get(x, y, 0), min, max, rgb);
        // through float, as the false-colour film holds it: once the range is the image's, the file's codes
        return codes.code((float) rgb[0]) << 16 | codes.code((float) rgb[1]) << 8 | codes.code((float) rgb[2]);
    }

    @Override
    public boolean takeIn(Film film, int x0, int y0, int x1, int y1) {
        double oldMin = min;
        double oldMax = max;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                min = Math.min(min, film.get(x, y, 0));
                max = Math.max(max, film.get(x, y, 0));
            }
        }
        return min != oldMin || max != oldMax;
    }
}

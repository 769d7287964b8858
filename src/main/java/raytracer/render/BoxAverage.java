package raytracer.render;

import raytracer.image.Film;
import raytracer.math.MutableRgb;

/**
 * The book's box filter (Suffern, listing 4.2): a pixel is the average of its own samples,
 * written to the film when the pixel is done.
 */
final class BoxAverage implements PixelSink {
    private final Film film;
    private int x;
    private int y;
    private int n;
    private double r;
    private double g;
    private double b;

    BoxAverage(Film film) {
        this.film = film;
    }

    @Override
    public void startPixel(int x, int y) {
        this.x = x;
        this.y = y;
        n = 0;
        r = 0;
        g = 0;
        b = 0;
    }

    @Override
    public void add(double u, double v, MutableRgb L) {
        r += L.r;
        g += L.g;
        b += L.b;
        n++;
    }

    @Override
    public void endPixel() {
        film.set(x, y, r / n, g / n, b / n);
    }
}

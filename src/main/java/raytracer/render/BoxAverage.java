package raytracer.render;

import raytracer.image.Film;
import raytracer.math.MutableRgb;

/**
 * The book's box filter (Suffern, listing 4.2): a pixel is the average of its own samples,
 * written to the film when the pixel is done.
 */
final class BoxAverage implements PixelSink {
    private final Film film;
    /** The image pixel at the film's top-left corner: (0, 0) for the whole image, a tile's corner for its own film. */
    private final int left;
    private final int top;
    private int x;
    private int y;
    private int n;
    private double r;
    private double g;
    private double b;

    BoxAverage(Film film) {
        this(film, 0, 0);
    }

    /** Into {@code film}, which holds the image's pixels from ({@code left}, {@code top}) on: a tile's own film. */
    BoxAverage(Film film, int left, int top) {
        this.film = film;
        this.left = left;
        this.top = top;
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
        film.set(x - left, y - top, r / n, g / n, b / n);
    }
}

package raytracer.render;

import raytracer.core.PixelFilter;
import raytracer.image.Film;
import raytracer.math.MutableRgb;

/**
 * The weighted sums that the samples of one tile leave, under a filter wider than a pixel, in the
 * tile's pixels and in a margin of {@link PixelFilter#reach} pixels around it (which belong to the
 * neighbouring tiles). Per pixel: the sums of w r, w g, w b and of w. A pixel's value is the sum
 * over every tile that reached it divided by the summed weight, added up after the render in the
 * order of the tile list, so the floating-point sums, and the image, do not depend on which thread
 * rendered which tile or when it finished ({@link FilteredImage}).
 */
final class FilteredTile implements PixelSink {
    private final PixelFilter filter;
    private final int reach;
    /** The pixel at the margin's top-left corner, and the rows' width and count with the margin. */
    private final int left;
    private final int top;
    private final int columns;
    private final int rows;
    private final double[] sums;
    /** The weights of the current sample per column and row offset -reach .. reach. */
    private final double[] wx;
    private final double[] wy;
    /** The pixel whose samples are being added. */
    private int x;
    private int y;

    /** For the tile of pixels x0 .. x1 - 1, y0 .. y1 - 1. */
    FilteredTile(PixelFilter filter, int x0, int y0, int x1, int y1) {
        this.filter = filter;
        this.reach = filter.reach();
        this.left = x0 - reach;
        this.top = y0 - reach;
        this.columns = x1 - x0 + 2 * reach;
        this.rows = y1 - y0 + 2 * reach;
        this.sums = new double[4 * columns * rows];
        this.wx = new double[2 * reach + 1];
        this.wy = new double[2 * reach + 1];
    }

    @Override
    public void startPixel(int x, int y) {
        this.x = x;
        this.y = y;
    }

    @Override
    public void add(double u, double v, MutableRgb L) {
        add(x, y, u, v, L.r, L.g, L.b);
    }

    @Override
    public void endPixel() {
        // the pixel's value is made once every tile that reaches it is done (FilteredImage)
    }

    /**
     * Adds a sample of radiance (r, g, b) taken at (x + fx, y + fy) in pixel (x, y) of this tile,
     * 0 &lt;= fx, fy &lt; 1, to every pixel whose centre lies within the filter's radius of it.
     */
    private void add(int x, int y, double fx, double fy, double r, double g, double b) {
        // the pixel k columns over has its centre at x + k + 0.5, |k + 0.5 - fx| from the sample
        for (int k = -reach; k <= reach; k++) {
            wx[k + reach] = filter.weight(k + 0.5 - fx);
            wy[k + reach] = filter.weight(k + 0.5 - fy);
        }
        // an end column may lie beyond the radius (at sigma 0.5 one always does): leave it out
        int first = wx[0] == 0 ? 1 : 0;
        int last = wx[2 * reach] == 0 ? 2 * reach - 1 : 2 * reach;
        int corner = (y - top - reach) * columns + (x - left - reach);
        for (int j = 0; j <= 2 * reach; j++) {
            double wj = wy[j];
            if (wj == 0) {
                continue;
            }
            int at = 4 * (corner + j * columns + first);
            for (int i = first; i <= last; i++, at += 4) {
                double w = wj * wx[i];
                sums[at] += w * r;
                sums[at + 1] += w * g;
                sums[at + 2] += w * b;
                sums[at + 3] += w;
            }
        }
    }

    /**
     * Writes to {@code film} each pixel of the tile (not its margin) from this tile's sums alone: a
     * preview, exact where the neighbouring tiles' samples do not reach, until the render resolves
     * every pixel. The pixel's own samples lie in this tile, so its summed weight is positive.
     */
    void estimate(Film film) {
        for (int y = top + reach; y < top + rows - reach; y++) {
            for (int x = left + reach; x < left + columns - reach; x++) {
                int at = 4 * ((y - top) * columns + (x - left));
                double w = sums[at + 3];
                film.set(x, y, sums[at] / w, sums[at + 1] / w, sums[at + 2] / w);
            }
        }
    }

    /** The tile's first pixel column and row, without the margin. */
    int x0() {
        return left + reach;
    }

    int y0() {
        return top + reach;
    }

    /**
     * Adds this tile's four sums for pixel (x, y), which must lie in the tile or its margin, to
     * {@code acc[0 .. 4)}.
     */
    void addSums(int x, int y, double[] acc) {
        int at = 4 * ((y - top) * columns + (x - left));
        for (int c = 0; c < 4; c++) {
            acc[c] += sums[at + c];
        }
    }
}

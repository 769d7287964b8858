package raytracer.render;

import raytracer.core.PixelFilter;
import raytracer.image.Film;

/**
 * The image under a filter wider than a pixel, made from the tiles' weighted sums
 * ({@link FilteredTile}) once every tile is rendered; and the check, before any ray is traced,
 * that the filter's reach lets it be made that way.
 */
final class FilteredImage {
    private FilteredImage() {
    }

    /**
     * Refuses, before any ray is traced, a filter that {@link #resolve} cannot gather: one whose
     * radius does not pass a pixel's half width (a sample at its pixel's edge could weigh nothing,
     * and a pixel all of whose samples did would be 0 / 0), or reaches past half a tile (a pixel
     * would then lie in the margins of more than two tiles along an axis).
     */
    static void check(PixelFilter filter) {
        if (filter.isBox()) {
            return;
        }
        int tile = Renderer.TILE_SIZE;
        if (!(filter.radius() > 0.5) || filter.reach() > tile / 2) {
            throw new IllegalArgumentException("the " + filter.name() + " filter's radius must be above 0.5 and below "
                                               + (tile / 2 + 0.5) + " pixels, got " + filter.radius());
        }
    }

    /**
     * Makes each pixel the weighted average of the samples that reached it: the sums of the tiles
     * whose margins hold it (its own and at most three neighbours, since the reach is at most half
     * a tile: at most two tiles along each axis), added in the order of the tile list, then divided
     * by the summed weight (which is positive, since the radius passes a pixel's half width, so
     * the pixel's own samples weigh something). Pixel by pixel, so no image of sums is held beside
     * the tiles'.
     */
    static void resolve(FilteredTile[] filtered, Film film, int reach) {
        int size = Renderer.TILE_SIZE;
        int width = film.width();
        int height = film.height();
        int columns = (width + size - 1) / size;
        int rows = (height + size - 1) / size;
        // each tile's place in the list, by its place in the grid of tiles
        int[] listIndex = new int[columns * rows];
        for (int i = 0; i < filtered.length; i++) {
            listIndex[filtered[i].y0() / size * columns + filtered[i].x0() / size] = i;
        }
        int[] near = new int[4];
        double[] acc = new double[4];
        for (int y = 0; y < height; y++) {
            int row0 = Math.max(0, y - reach) / size;
            int row1 = Math.min(height - 1, y + reach) / size;
            for (int x = 0; x < width; x++) {
                int column0 = Math.max(0, x - reach) / size;
                int column1 = Math.min(width - 1, x + reach) / size;
                int n = 0;
                for (int row = row0; row <= row1; row++) {
                    for (int column = column0; column <= column1; column++) {
                        // insertion into list order
                        int index = listIndex[row * columns + column];
                        int k = n++;
                        while (k > 0 && near[k - 1] > index) {
                            near[k] = near[k - 1];
                            k--;
                        }
                        near[k] = index;
                    }
                }
                acc[0] = 0;
                acc[1] = 0;
                acc[2] = 0;
                acc[3] = 0;
                for (int k = 0; k < n; k++) {
                    filtered[near[k]].addSums(x, y, acc);
                }
                film.set(x, y, acc[0] / acc[3], acc[1] / acc[3], acc[2] / acc[3]);
            }
        }
    }
}

package raytracer.render;

import java.util.ArrayList;
import java.util.List;

/**
 * The order in which the workers take the image's tiles: the row-major list of square tiles
 * permuted by bit reversal of the index (van der Corput), so that every aligned run of 2^k
 * successive tiles, each half the fork/join split hands a worker among them ({@link TileRange}),
 * is spread over the whole image.
 *
 * <p>Why: the JIT compiles the hot loops from what the first tiles did. Taken row by row, those
 * were a strip of floor or sky, where a shadow ray never meets a triangle behind its origin;
 * compiled without that branch, the triangle test was thrown away and recompiled once the rows
 * reached the object, during the first render (docs/performance.md, "Tile order").
 */
final class TileOrder {
    private TileOrder() {
    }

    /** The tiles (x0, y0, x1, y1) of a width x height image, {@link Renderer#TILE_SIZE} pixels square or cut by its edge, in the workers' order. */
    static List<int[]> tiles(int width, int height) {
        int size = Renderer.TILE_SIZE;
        List<int[]> rowMajor = new ArrayList<>();
        for (int y = 0; y < height; y += size) {
            for (int x = 0; x < width; x += size) {
                rowMajor.add(new int[] {x, y, Math.min(x + size, width), Math.min(y + size, height)});
            }
        }
        int n = rowMajor.size();
        int bits = 32 - Integer.numberOfLeadingZeros(n - 1);
        List<int[]> spread = new ArrayList<>(n);
        for (int i = 0; i < 1 << bits; i++) {
            // bits is 0 for a single tile, and a shift by 32 would be no shift in Java
            int j = bits == 0 ? 0 : Integer.reverse(i) >>> (32 - bits);
            if (j < n) {
                spread.add(rowMajor.get(j));
            }
        }
        return spread;
    }
}

package raytracer.render;

import java.util.ArrayList;
import java.util.List;
import raytracer.core.GeometricObject;

/**
 * The order in which the workers take the tiles. The JIT compiles the hot code from what the
 * first few hundred rays did, and throws it away (an {@code unstable_if} trap, then a recompile)
 * when a branch it never saw taken is taken: the first tiles must show every kind of ray.
 *
 * <p>{@link #tiles}: the row-major list permuted by bit reversal of the index (van der Corput), so
 * that every aligned run of 2^k successive tiles, each half the fork/join split hands a worker
 * among them ({@link TileRange}), is spread over the whole image (taken row by row, the first tiles were a strip of floor or sky,
 * where a shadow ray never meets a triangle behind its origin: docs/performance.md, "Cold and warm runs").
 *
 * <p>{@link #warmUpFirst}: spread over the image is not enough when an object fills only part of
 * it. On the dragon's bench frame the first two tiles of both workers were floor alone: camera
 * rays never entered the dragon's tree while the JIT profiled it (only the floor's shadow rays
 * did, all going up), and the slab test and the triangle tests were recompiled half a second into
 * the first render. So the tiles are first ranked by how many objects their camera rays can meet
 * ({@link TileObjects}), most first (row-major among equals), and that ranking is dealt out by bit
 * reversal: the first tile of every half, quarter, ... of the list is among the richest. With every
 * tile as rich as the others this is {@link #tiles} itself.
 */
final class TileOrder {
    private TileOrder() {
    }

    /**
     * The tiles (x0, y0, x1, y1) of a width x height image, {@link Renderer#TILE_SIZE} pixels square
     * or cut by its edge, row-major permuted by bit reversal: the order in which a wide filter's sums
     * are added ({@link FilteredImage}), and the order of rendering but for {@link #warmUpFirst}.
     */
    static List<int[]> tiles(int width, int height) {
        int size = Renderer.TILE_SIZE;
        List<int[]> rowMajor = new ArrayList<>();
        for (int y = 0; y < height; y += size) {
            for (int x = 0; x < width; x += size) {
                rowMajor.add(new int[] {x, y, Math.min(x + size, width), Math.min(y + size, height)});
            }
        }
        List<int[]> spread = new ArrayList<>(rowMajor.size());
        for (int j : bitReversed(rowMajor.size())) {
            spread.add(rowMajor.get(j));
        }
        return spread;
    }

    /** 0 .. n - 1 in the order of their bit reversals over the fewest bits that hold n - 1. */
    private static int[] bitReversed(int n) {
        int bits = 32 - Integer.numberOfLeadingZeros(Math.max(0, n - 1));
        int[] order = new int[n];
        int k = 0;
        for (int i = 0; i < 1 << bits; i++) {
            // bits is 0 for a single tile, and a shift by 32 would be no shift in Java
            int j = bits == 0 ? 0 : Integer.reverse(i) >>> (32 - bits);
            if (j < n) {
                order[k++] = j;
            }
        }
        return order;
    }

    /**
     * The positions in {@code tiles} (a {@link #tiles} list of a grid whose tiles are {@code size}
     * pixels wide) in the order to render them: ranked by the number of objects each tile's camera
     * rays can meet ({@code objects[i]}, null meaning all {@code everything} of them; no ranking
     * when {@code objects} is null), ties row-major, and dealt out by bit reversal.
     */
    static int[] warmUpFirst(List<int[]> tiles, GeometricObject[][] objects, int everything, int size) {
        int n = tiles.size();
        int columns = 0;
        for (int[] t : tiles) {
            columns = Math.max(columns, t[0] / size + 1);
        }
        // the positions in row-major order, then a stable counting sort of them by objects seen, most
        // first: no comparator (a lambda's first call costs a cold JVM some 30 ms of the first frame)
        int[] byRowMajor = new int[n];
        int most = 0;
        for (int i = 0; i < n; i++) {
            int[] t = tiles.get(i);
            byRowMajor[t[1] / size * columns + t[0] / size] = i;
            most = Math.max(most, seen(objects, i, everything));
        }
        int[] start = new int[most + 2];
        for (int i = 0; i < n; i++) {
            start[most - seen(objects, i, everything) + 1]++;
        }
        for (int c = 1; c < start.length; c++) {
            start[c] += start[c - 1];
        }
        int[] ranked = new int[n];
        for (int position : byRowMajor) {
            ranked[start[most - seen(objects, position, everything)]++] = position;
        }
        int[] order = new int[n];
        int[] deal = bitReversed(n);
        for (int k = 0; k < n; k++) {
            order[k] = ranked[deal[k]];
        }
        return order;
    }

    private static int seen(GeometricObject[][] objects, int tile, int everything) {
        return objects == null || objects[tile] == null ? everything : objects[tile].length;
    }


    /**
     * Fails unless {@code indices} name tiles of the list {@code tiles} of a width x height image,
     * each once: two workers would render a tile given twice into one tile's arrays at once.
     */
    static void checkIndices(int[] indices, List<int[]> tiles, int width, int height) {
        boolean[] given = new boolean[tiles.size()];
        for (int index : indices) {
            if (index < 0 || index >= tiles.size()) {
                throw new IllegalArgumentException("tile " + index + " is not one of the " + tiles.size() + " tiles of a "
                                                   + width + "x" + height + " image");
            }
            if (given[index]) {
                throw new IllegalArgumentException("tile " + index + " is given twice");
            }
            given[index] = true;
        }
    }
}

package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The order of the tiles: every pixel in exactly one tile, and early tiles spread over the image. */
class TileOrderTest {
    @Test
    void everyPixelIsInExactlyOneTile() {
        int[][] sizes = {{1, 1}, {32, 32}, {33, 1}, {1920, 1080}, {97, 65}, {64, 31}, {1, 300}};
        for (int[] size : sizes) {
            int width = size[0];
            int height = size[1];
            int[] covered = new int[width * height];
            List<int[]> tiles = TileOrder.tiles(width, height);
            for (int[] t : tiles) {
                assertTrue(t[0] < t[2] && t[1] < t[3] && t[2] <= width && t[3] <= height, "a tile inside the image");
                for (int y = t[1]; y < t[3]; y++) {
                    for (int x = t[0]; x < t[2]; x++) {
                        covered[y * width + x]++;
                    }
                }
            }
            for (int p = 0; p < covered.length; p++) {
                assertEquals(1, covered[p], width + "x" + height + ": pixel " + p % width + ", " + p / width);
            }
            int columns = (width + Renderer.TILE_SIZE - 1) / Renderer.TILE_SIZE;
            int rows = (height + Renderer.TILE_SIZE - 1) / Renderer.TILE_SIZE;
            assertEquals(columns * rows, tiles.size(), width + "x" + height + ": tiles");
        }
    }

    @Test
    void theFirstTilesOfEachHalfReachEveryQuarterOfTheImage() {
        // the JIT compiles from the first tiles each worker renders: a worker takes a half of the
        // list (the split's), and its first eighth must already reach all four quarters
        int width = 1920;
        int height = 1080;
        List<int[]> tiles = TileOrder.tiles(width, height);
        int half = tiles.size() / 2;
        for (int from : new int[] {0, half}) {
            Set<Integer> quarters = new HashSet<>();
            for (int i = from; i < from + half / 8; i++) {
                int[] t = tiles.get(i);
                quarters.add((t[0] < width / 2 ? 0 : 1) + (t[1] < height / 2 ? 0 : 2));
            }
            assertEquals(4, quarters.size(), "quarters reached by the first tiles from " + from);
        }
    }

    /**
     * The tiles whose camera rays can meet the most objects come first in each half (the
     * bench dragon's first tiles were floor alone, and the JIT compiled the slab and triangle tests
     * without the camera rays' branches); with all tiles alike the order is the spread itself.
     */
    @Test
    void theRichestTilesStartEveryHalfAndAnOrderOfEqualsIsTheSpread() {
        List<int[]> tiles = TileOrder.tiles(1920, 1080);
        int n = tiles.size();
        int[] alike = TileOrder.warmUpFirst(tiles, null, 2, Renderer.TILE_SIZE);
        for (int i = 0; i < n; i++) {
            assertEquals(i, alike[i], "no objects known: the spread order");
        }
        // an object in the middle of the image, seen by the tiles within 300 pixels of its centre
        raytracer.core.GeometricObject[][] seen = new raytracer.core.GeometricObject[n][];
        raytracer.core.GeometricObject[] floor = {null};
        raytracer.core.GeometricObject[] both = {null, null};
        int rich = 0;
        for (int i = 0; i < n; i++) {
            int[] t = tiles.get(i);
            boolean near = Math.abs(t[0] - 960) < 300 && Math.abs(t[1] - 540) < 300;
            seen[i] = near ? both : floor;
            rich += near ? 1 : 0;
        }
        int[] order = TileOrder.warmUpFirst(tiles, seen, 2, Renderer.TILE_SIZE);
        Set<Integer> positions = new HashSet<>();
        for (int index : order) {
            positions.add(index);
        }
        assertEquals(n, positions.size(), "every tile once");
        assertTrue(rich < n / 4, rich + " rich tiles");
        for (int start : new int[] {0, n / 2, n / 4, 3 * n / 4}) {
            assertEquals(2, seen[order[start]].length, "the tile starting at " + start + " sees both objects");
        }
    }
}

package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.World;
import raytracer.filters.Gaussian;
import raytracer.image.Film;
import raytracer.io.scene.SceneLoader;

/**
 * An image rendered in parts ({@link Renderer#renderTiles}: runs of the tile list, on other pools,
 * in any order) and assembled ({@link TileImage}) is the image rendered whole, to the bit, under
 * the box filter and under Gaussians whose margins reach one and two tiles' neighbours; and the
 * assembly refuses a missing, doubled or misplaced tile.
 */
class RenderTilesTest {

    @ParameterizedTest(name = "{0}x{1}, filter {2}")
    @CsvSource({"100, 70, box", "100, 70, 0.5", "33, 65, 2.0", "32, 32, 1.0", "7, 5, 0.5"})
    void partsAssembledAreTheWholeImage(int width, int height, String filter) throws Exception {
        World world = SceneLoader.load(Path.of("scenes", "default.yaml")).world();
        world.prepare();
        PixelFilter f = filter.equals("box") ? PixelFilter.BOX : new Gaussian(Double.parseDouble(filter));
        world.setViewPlane(world.viewPlane().withResolution(width, height).withSamples(4).withFilter(f));
        Film whole = new Film(width, height);
        try (Workers workers = new Workers(2)) {
            new Renderer(world, RayTreeSettings.FULL_TREE, workers, 7).render(whole);
        }
        int count = Renderer.tiles(width, height).size();
        // runs of the list, each by a renderer and pool of its own, taken in a shuffled order
        List<int[]> runs = new ArrayList<>();
        for (int from = 0, k = 0; from < count; k++) {
            int to = Math.min(count, from + 1 + k % 3);
            int[] run = new int[to - from];
            for (int i = 0; i < run.length; i++) {
                run[i] = from + i;
            }
            runs.add(run);
            from = to;
        }
        Collections.shuffle(runs, new Random(3));
        List<TilePixels> parts = new ArrayList<>();
        for (int[] run : runs) {
            try (Workers workers = new Workers(1 + run.length % 2)) {
                RenderedTiles rendered = new Renderer(world, RayTreeSettings.FULL_TREE, workers, 7).renderTiles(run);
                assertEquals(run.length, rendered.tiles().length);
                long pixels = 0;
                for (TilePixels t : rendered.tiles()) {
                    pixels += (long) (t.x1() - t.x0()) * (t.y1() - t.y0());
                }
                assertEquals(4 * pixels, rendered.stats().primaryRays(), "4 camera rays per pixel of the run's tiles");
                Collections.addAll(parts, rendered.tiles());
            }
        }
        Film assembled = new Film(width, height);
        TileImage.assemble(parts, f, assembled);
        int differing = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                for (int c = 0; c < 3; c++) {
                    differing += Float.floatToRawIntBits(whole.get(x, y, c)) == Float.floatToRawIntBits(assembled.get(x, y, c)) ? 0 : 1;
                }
            }
        }
        assertEquals(0, differing, "channels that differ from the whole render");
    }

    @ParameterizedTest(name = "filter {0}")
    @CsvSource({"box", "0.5"})
    void theAssemblyRefusesAWrongSetOfTiles(String filter) throws Exception {
        World world = SceneLoader.load(Path.of("scenes", "default.yaml")).world();
        world.prepare();
        PixelFilter f = filter.equals("box") ? PixelFilter.BOX : new Gaussian(0.5);
        world.setViewPlane(world.viewPlane().withResolution(70, 40).withSamples(1).withFilter(f));
        TilePixels[] tiles;
        try (Workers workers = new Workers(1)) {
            tiles = new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1).renderTiles(new int[] {0, 1, 2, 3, 4, 5}).tiles();
            assertThrows(IllegalArgumentException.class, () -> new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1)
                .renderTiles(new int[] {6}), "a 70x40 image has 6 tiles");
            assertTrue(assertThrows(IllegalArgumentException.class, () -> new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1)
                .renderTiles(new int[] {2, 3, 2})).getMessage().contains("tile 2 is given twice"));
        }
        Film film = new Film(70, 40);
        List<TilePixels> missing = List.of(tiles).subList(0, 5);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> TileImage.assemble(missing, f, film)).getMessage()
                       .contains("tile 5 of 6 is missing"));
        List<TilePixels> twice = new ArrayList<>(List.of(tiles));
        twice.add(tiles[2]);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> TileImage.assemble(twice, f, film)).getMessage()
                       .contains("tile 2 is given twice"));
        assertThrows(IllegalArgumentException.class, () -> TileImage.assemble(List.of(tiles), f, new Film(71, 40)),
                     "a tile placed for another size");
        assertThrows(IllegalArgumentException.class, () -> TileImage.assemble(List.of(tiles), f.isBox() ? new Gaussian(0.5) : PixelFilter.BOX,
                                                                             film), "another filter");
    }
}

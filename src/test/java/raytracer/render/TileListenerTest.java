package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.World;
import raytracer.filters.Gaussian;
import raytracer.image.Film;
import raytracer.io.scene.SceneLoader;

/**
 * A render that tells a listener of its tiles (the {@code --show} window's hook): each tile once,
 * together the whole image, its pixels in the film when told (the box filter's final values, the
 * Gaussian's estimate from the tile's own samples), and the image the same to the bit as without a
 * listener.
 */
class TileListenerTest {
    private static final int WIDTH = 100;
    private static final int HEIGHT = 70;

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void everyTileIsToldOnceWithItsPixelsAndTheImageIsTheSame(boolean gaussian) throws Exception {
        World world = SceneLoader.load(Path.of("scenes", "default.yaml")).world();
        world.prepare();
        world.setViewPlane(world.viewPlane().withResolution(WIDTH, HEIGHT).withSamples(4)
                               .withFilter(gaussian ? new Gaussian(Gaussian.DEFAULT_STDDEV) : PixelFilter.BOX));
        Film plain = new Film(WIDTH, HEIGHT);
        Film shown = new Film(WIDTH, HEIGHT);
        int[] told = new int[WIDTH * HEIGHT];
        List<String> wrong = new ArrayList<>();
        try (Workers workers = new Workers(3)) {
            new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1).render(plain);
            new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1).render(shown, (x0, y0, x1, y1) -> {
                synchronized (told) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) {
                            told[y * WIDTH + x]++;
                            // on the worker, when told: a pixel the tile has not written is 0 in every channel
                            if (shown.get(x, y, 0) == 0 && shown.get(x, y, 1) == 0 && shown.get(x, y, 2) == 0) {
                                wrong.add(x + ", " + y);
                            }
                        }
                    }
                }
            });
        }
        assertEquals(List.of(), wrong, "pixels not written when their tile was told");
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                assertEquals(1, told[y * WIDTH + x], "times pixel " + x + ", " + y + " was told");
                for (int c = 0; c < 3; c++) {
                    assertEquals(Float.floatToIntBits(plain.get(x, y, c)), Float.floatToIntBits(shown.get(x, y, c)),
                                 "pixel " + x + ", " + y + ", channel " + c);
                }
            }
        }
        assertTrue(plain.get(WIDTH / 2, HEIGHT - 1, 0) > 0, "the scene is lit");
    }
}

package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.image.Film;

/**
 * The renderer drops a NaN or infinite sample (Renderer.renderPixel), counts it, and keeps the pixel
 * finite: the pixel is the sum of its finite samples over all n samples, a dropped one adding black.
 * The count must be the same for any number of threads.
 */
class NonFiniteSamplesTest {

    @Test
    void nonFiniteSamplesAreCountedAndDropped() {
        for (int threads : new int[] {1, 3}) {
            Film film = new Film(NonFiniteScene.W, NonFiniteScene.H);
            RenderStats stats = Renders.render(NonFiniteScene.world(), threads, 1, film);
            assertEquals(NonFiniteScene.NON_FINITE_SAMPLES, stats.nonFiniteSamples(), threads + " threads");
            for (int y = 0; y < NonFiniteScene.H; y++) {
                for (int x = 0; x < NonFiniteScene.W; x++) {
                    double kept = switch (x) {
                        case 4, 6, 10, 11 -> 0.5;  // 2 of the 4 samples dropped
                        case 5 -> 0;               // all 4 dropped
                        default -> 1;
                    };
                    for (int c = 0; c < 3; c++) {
                        assertTrue(Float.isFinite(film.get(x, y, c)), "pixel " + x + "," + y);
                    }
                    assertEquals(kept * NonFiniteScene.COLOR.r(), film.get(x, y, 0), 1e-7, "red of pixel " + x + "," + y);
                    assertEquals(kept * NonFiniteScene.COLOR.g(), film.get(x, y, 1), 1e-7, "green of pixel " + x + "," + y);
                    assertEquals(kept * NonFiniteScene.COLOR.b(), film.get(x, y, 2), 1e-7, "blue of pixel " + x + "," + y);
                }
            }
        }
    }
}

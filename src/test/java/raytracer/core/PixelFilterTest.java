package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.filters.Gaussian;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.RGBColor;
import raytracer.render.Renders;
import raytracer.samplers.Samplers;

/** The book's box filter: weight 1 inside a pixel's half width, nothing beyond, and no reach. */
class PixelFilterTest {
    /** The lit pixel of {@link #render}, in an image of 8 x 6. */
    private static final int X = 3;
    private static final int Y = 2;

    @Test
    void theBoxWeighsOneInsideItsHalfPixelAndNothingBeyond() {
        for (double d : new double[] {0, 0.1, 0.25, 0.4999, -0.4999}) {
            assertEquals(1, PixelFilter.BOX.weight(d), "d = " + d);
        }
        for (double d : new double[] {0.5, 0.75, -2}) {
            assertEquals(0, PixelFilter.BOX.weight(d), "d = " + d);
        }
    }

    /**
     * Renders 8 x 6 pixels at 16 samples where only the samples landing in pixel (X, Y) bring
     * light: a camera whose rays start at the sample's image position (px, py) and a tracer that
     * gives 1 to a ray starting in that pixel's square and 0 to any other, so that which pixel a
     * sample belongs to is read off exactly.
     */
    private static Film render(PixelFilter filter, String sampler) {
        Camera atTheSample = (vp, px, py, lensX, lensY, out) -> out.set(px, py, 0, 0, 0, -1);
        World world = new World(new ViewPlane(8, 6, 16, Samplers.byName(sampler), 0, 1, filter), atTheSample,
                                new Ambient(0, RGBColor.BLACK));
        world.setTracer(w -> (ray, depth, scratch, out) -> {
            double lit = Math.floor(ray.ox) == X && Math.floor(ray.oy) == Y ? 1 : 0;
            out.set(lit, lit, lit);
        });
        world.prepare();
        Film film = new Film(8, 6);
        Renders.render(world, 2, 1, film);
        return film;
    }

    @Test
    void theBoxReachesNoOtherPixel() {
        for (String sampler : new String[] {"regular", "random", "jittered", "multi-jittered", "hammersley", "sobol"}) {
            Film film = render(PixelFilter.BOX, sampler);
            for (int y = 0; y < 6; y++) {
                for (int x = 0; x < 8; x++) {
                    // the lit pixel averages its own samples, all of them 1; no other pixel takes any of them
                    assertEquals(x == X && y == Y ? 1 : 0, film.get(x, y, 0), 0, sampler + ", pixel " + x + ", " + y);
                }
            }
        }
    }

    /** The same render through a filter that does reach the neighbours: the test above can see a reach. */
    @Test
    void aWiderFilterSharesThePixelsSamplesWithItsNeighbours() {
        Film film = render(new Gaussian(Gaussian.DEFAULT_STDDEV), "multi-jittered");
        assertTrue(film.get(X, Y, 0) < 1, "the lit pixel also averages its neighbours' dark samples");
        assertTrue(film.get(X + 1, Y, 0) > 0 && film.get(X, Y - 1, 0) > 0 && film.get(X - 1, Y + 1, 0) > 0, "the neighbours take some");
        assertEquals(0, film.get(X + 3, Y, 0), 0, "three pixels over, beyond the radius of 2");
    }
}

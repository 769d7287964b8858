package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.core.Camera;
import raytracer.core.PixelFilter;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.filters.Gaussian;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.Hashes;
import raytracer.math.MutableRgb;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.samplers.Samplers;

/**
 * Rendering under the Gaussian filter: a pixel is the filter-weighted average of the samples
 * around it, computed here independently from the formula; the image does not depend on the
 * thread count; the box filter's images are the plain averages they always were.
 */
class FilteredRenderTest {
    private static final Gaussian GAUSSIAN = new Gaussian(Gaussian.DEFAULT_STDDEV);

    @Test
    void anEdgeIsTheFilterWeightedAverageOfTheSamplesAroundEachPixel() {
        // radiance 1 left of x = 7.3, 0 right of it; the regular sampler's 8 x 8 grid puts samples
        // at (x + (i + 0.5) / 8, y + (j + 0.5) / 8). The weights are separable and the radiance does
        // not change with y, so a pixel is sum w(x_s - c) step(x_s) / sum w(x_s - c) over the sample
        // columns x_s within the image: the row weights cancel.
        int width = 16;
        int height = 5;
        double edge = 7.3;
        Film film = render(world(width, height, 64, "regular", (px, py) -> px < edge ? 1 : 0), 2);
        for (int x = 0; x < width; x++) {
            double centre = x + 0.5;
            double lit = 0;
            double all = 0;
            for (int column = 0; column < width; column++) {
                for (int i = 0; i < 8; i++) {
                    double xs = column + (i + 0.5) / 8;
                    double w = GAUSSIAN.exactWeight(xs - centre);
                    all += w;
                    lit += xs < edge ? w : 0;
                }
            }
            for (int y = 0; y < height; y++) {
                assertEquals(lit / all, film.get(x, y, 0), 1e-6, "pixel " + x + ", " + y);
            }
        }
        // the edge is softened across the pixels within the radius of it, and only those
        assertEquals(1, film.get(4, 2, 0), 1e-6);
        assertTrue(film.get(6, 2, 0) < 0.999 && film.get(6, 2, 0) > 0.9, "softened: " + film.get(6, 2, 0));
        assertTrue(film.get(8, 2, 0) > 0.001 && film.get(8, 2, 0) < 0.1, "softened: " + film.get(8, 2, 0));
        assertEquals(0, film.get(10, 2, 0), 1e-6);
    }

    @Test
    void aConstantImageStaysConstantUpToTheEdges() {
        Film film = render(world(37, 29, 4, "random", (px, py) -> 0.25), 2);
        for (int y = 0; y < 29; y++) {
            for (int x = 0; x < 37; x++) {
                assertEquals(0.25, film.get(x, y, 1), 1e-7, "pixel " + x + ", " + y);
            }
        }
    }

    @Test
    void theImageIsTheSameForAnyThreadCount() {
        // radiance that differs per sample, over several tiles (70 x 45 pixels: 3 x 2 tiles of 32)
        World world = world(70, 45, 4, "multi-jittered", (px, py) -> (Hashes.mix(Double.doubleToLongBits(px * 31 + py)) >>> 11) * 0x1p-53);
        Film one = render(world, 1);
        for (int threads : new int[] {2, 3}) {
            Film other = render(world, threads);
            for (int y = 0; y < 45; y++) {
                for (int x = 0; x < 70; x++) {
                    assertEquals(one.get(x, y, 0), other.get(x, y, 0), 0, threads + " threads, pixel " + x + ", " + y);
                }
            }
        }
    }

    @Test
    void aSampleThatIsNotFiniteCountsAsBlackAndIsCounted() {
        // every sample in column 3 is NaN: the pixels near it are darker, none is NaN
        World world = world(8, 4, 4, "jittered", (px, py) -> px >= 3 && px < 4 ? Double.NaN : 1);
        Film film = new Film(8, 4);
        RenderStats stats = Renders.render(world, 2, 1, film);
        assertEquals(4L * 4, stats.nonFiniteSamples(), "the NaN samples of column 3");
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 8; x++) {
                float v = film.get(x, y, 0);
                assertTrue(Float.isFinite(v) && v >= 0 && v <= 1, "pixel " + x + ", " + y + ": " + v);
            }
            assertTrue(film.get(3, y, 0) < 0.5, "column 3 mostly black: " + film.get(3, y, 0));
            assertEquals(1, film.get(7, y, 0), 1e-6, "column 7 beyond the radius");
        }
    }

    @Test
    void theBoxFilterAveragesEachPixelsOwnSamples() {
        // the book's path: (x + 0.5 after the regular 1-sample grid) the pixel holds its own sample only
        World world = world(6, 3, 1, "regular", (px, py) -> px);
        world.setViewPlane(world.viewPlane().withFilter(PixelFilter.BOX));
        Film film = render(world, 2);
        for (int x = 0; x < 6; x++) {
            assertEquals(x + 0.5, film.get(x, 1, 0), 1e-6);
        }
    }

    @Test
    void aFilterTheTilesCannotGatherIsRefusedBeforeRendering() {
        // radius 0.5: a sample on its pixel's edge weighs nothing; reach 17: more than two tiles per axis
        for (double radius : new double[] {0.5, 17.2}) {
            PixelFilter tent = new PixelFilter() {
                @Override
                public String name() {
                    return "tent";
                }

                @Override
                public double radius() {
                    return radius;
                }

                @Override
                public double weight(double d) {
                    return Math.max(0, 1 - Math.abs(d) / radius);
                }
            };
            World world = world(4, 4, 1, "hammersley", (px, py) -> 1);
            world.setViewPlane(world.viewPlane().withFilter(tent));
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> render(world, 1));
            assertEquals("the tent filter's radius must be above 0.5 and below 16.5 pixels, got " + radius, e.getMessage());
        }
    }

    private interface Radiance {
        double at(double px, double py);
    }

    /** A world whose camera puts the sample position into the ray and whose tracer returns radiance(px, py) in all channels. */
    private static World world(int width, int height, int spp, String sampler, Radiance radiance) {
        ViewPlane vp = new ViewPlane(width, height, spp, Samplers.byName(sampler), 1, 1, GAUSSIAN);
        Camera camera = (plane, px, py, lensX, lensY, out) -> out.set(px, py, 0, 0, 0, 1);
        World world = new World(vp, camera, new Ambient(0, RGBColor.WHITE));
        world.setTracer(w -> new Tracer() {
            @Override
            public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
                double v = radiance.at(ray.ox, ray.oy);
                out.set(v, v, v);
            }
        });
        world.prepare();
        return world;
    }

    private static Film render(World world, int threads) {
        Film film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
        Renders.render(world, threads, 3, film);
        return film;
    }
}

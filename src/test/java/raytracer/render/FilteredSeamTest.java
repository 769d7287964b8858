package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
 * The Gaussian filter across the seams of the tiles: an image of several tiles, each sample of a
 * made-up radiance, against the filtered image computed here by brute force over every sample of
 * the image (the regular sampler puts them at known places). A tile whose samples did not reach
 * its neighbours' pixels, or reached the wrong ones, fails here.
 */
class FilteredSeamTest {
    private static final int WIDTH = 70;
    private static final int HEIGHT = 45;
    /** The regular sampler's k x k grid in each pixel. */
    private static final int K = 3;

    @Test
    void everyPixelIsTheWeightedAverageOfAllTheSamplesAroundIt() {
        for (double stddev : new double[] {0.5, 1.0, 2.0}) {
            Gaussian filter = new Gaussian(stddev);
            Film film = render(filter);
            double worst = 0;
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    double expected = bruteForce(filter, x, y);
                    worst = Math.max(worst, Math.abs(expected - film.get(x, y, 0)));
                    assertEquals(expected, film.get(x, y, 0), 2e-5, "stddev " + stddev + ", pixel " + x + ", " + y);
                }
            }
            assertTrue(worst > 0, "float pixels against double sums differ somewhere: the comparison is real");
        }
    }

    /** Sum over every sample s of the image of w(xs - cx) w(ys - cy) L(s), over the sum of the weights. */
    private static double bruteForce(Gaussian filter, int x, int y) {
        double sum = 0;
        double weights = 0;
        for (int py = 0; py < HEIGHT; py++) {
            for (int px = 0; px < WIDTH; px++) {
                for (int j = 0; j < K; j++) {
                    for (int i = 0; i < K; i++) {
                        double sx = px + (i + 0.5) / K;
                        double sy = py + (j + 0.5) / K;
                        double w = filter.exactWeight(sx - (x + 0.5)) * filter.exactWeight(sy - (y + 0.5));
                        sum += w * radiance(sx, sy);
                        weights += w;
                    }
                }
            }
        }
        return sum / weights;
    }

    /** A value in [0, 1) that changes from sample to sample. */
    private static double radiance(double sx, double sy) {
        return (Hashes.mix(Double.doubleToLongBits(sx), Double.doubleToLongBits(sy)) >>> 11) * 0x1p-53;
    }

    private static Film render(PixelFilter filter) {
        ViewPlane vp = new ViewPlane(WIDTH, HEIGHT, K * K, Samplers.byName("regular"), 1, 1, filter);
        Camera camera = (plane, px, py, lensX, lensY, out) -> out.set(px, py, 0, 0, 0, 1);
        World world = new World(vp, camera, new Ambient(0, RGBColor.WHITE));
        world.setTracer(w -> new Tracer() {
            @Override
            public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
                double v = radiance(ray.ox, ray.oy);
                out.set(v, v, v);
            }
        });
        world.prepare();
        Film film = new Film(WIDTH, HEIGHT);
        Renders.render(world, 2, 1, film);
        return film;
    }
}

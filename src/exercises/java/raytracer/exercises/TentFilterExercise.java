package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.Camera;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.MutableRgb;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.render.Renderer;
import raytracer.render.Workers;
import raytracer.samplers.Samplers;

/**
 * Exercise 9: the tent filter, w(d) = max(0, 1 - |d| / r) along each axis (pbrt-v3, section
 * 7.8.1). Checked against the formula, and through the renderer: an image of a vertical edge
 * must be, pixel by pixel, the tent-weighted average of the samples around it, computed here.
 */
@Tag("exercise")
class TentFilterExercise {
    private static Constructor<? extends PixelFilter> tent;

    @BeforeAll
    static void findTheClass() {
        tent = Student.constructor(9, "raytracer.filters.Tent", PixelFilter.class, double.class);
    }

    private static PixelFilter tent(double radius) {
        return Student.create(tent, radius);
    }

    @Test
    void theWeightIsTheTent() {
        for (double r : new double[] {0.75, 1, 1.5, 3, 8}) {
            PixelFilter f = tent(r);
            assertEquals(r, f.radius(), "Tent(" + r + ").radius() must be the radius it was made with");
            assertEquals("tent", f.name(), "Tent(" + r + ").name() must be \"tent\", the name scenes and --filter use");
            assertFalse(f.isBox(), "only the book's box is averaged without weights");
            for (double d = -r - 1; d <= r + 1; d += 0.0625) {
                assertEquals(Math.max(0, 1 - Math.abs(d) / r), f.weight(d), 1e-12, "Tent(" + r + ").weight(" + d
                                                                                     + ") must be max(0, 1 - |d| / r)");
            }
        }
    }

    @Test
    void aRadiusNotAboveHalfAPixelOrAboveEightIsRefused() {
        for (double bad : new double[] {0, 0.4, 0.5, 8.5, Double.NaN}) {
            String rule = "Tent(" + bad + "): a radius must be above 0.5 and at most 8 pixels, else IllegalArgumentException";
            InvocationTargetException e = assertThrows(InvocationTargetException.class, () -> tent.newInstance(bad), rule);
            assertEquals(IllegalArgumentException.class, e.getCause().getClass(), rule + ", got " + e.getCause());
        }
    }

    @Test
    void anEdgeIsTheTentWeightedAverageOfTheSamplesAroundEachPixel() {
        // radiance 1 left of x = 31.7, 0 right of it, over 48 x 3 pixels: the edge lies at the seam of
        // two tiles (x = 32), so pixels 30 to 33 mix both tiles' samples; the regular sampler's 4 x 4 grid. The weights are separable and the radiance does not change with y,
        // so a pixel is sum w(x_s - c) step(x_s) / sum w(x_s - c) over the image's sample columns.
        int width = 48;
        int height = 3;
        double edge = 31.7;
        PixelFilter filter = tent(1.5);
        ViewPlane vp = new ViewPlane(width, height, 16, Samplers.byName("regular"), 1, 1, filter);
        Camera camera = (plane, px, py, lensX, lensY, out) -> out.set(px, py, 0, 0, 0, 1);
        World world = new World(vp, camera, new Ambient(0, RGBColor.WHITE));
        world.setTracer(w -> new Tracer() {
            @Override
            public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
                double v = ray.ox < edge ? 1 : 0;
                out.set(v, v, v);
            }
        });
        world.prepare();
        Film film = new Film(width, height);
        try (Workers workers = new Workers(2)) {
            new Renderer(world, RayTreeSettings.FULL_TREE, workers, 1).render(film);
        }
        for (int x = 0; x < width; x++) {
            double lit = 0;
            double all = 0;
            for (int column = 0; column < width; column++) {
                for (int i = 0; i < 4; i++) {
                    double xs = column + (i + 0.5) / 4;
                    double w = Math.max(0, 1 - Math.abs(xs - (x + 0.5)) / 1.5);
                    all += w;
                    lit += xs < edge ? w : 0;
                }
            }
            for (int y = 0; y < height; y++) {
                assertEquals(lit / all, film.get(x, y, 0), 1e-6, "pixel (" + x + ", " + y + ") must be the tent-weighted average of "
                                                                 + "the samples within 1.5 pixels of its centre, " + lit / all);
            }
        }
    }
}

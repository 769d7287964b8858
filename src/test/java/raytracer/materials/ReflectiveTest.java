package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.Fresnel;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.shapes.Sphere;
import raytracer.tracers.Whitted;

/** A mirror sphere in a white world shows its reflected fraction directly, pixel by pixel. */
class ReflectiveTest {
    private static final int SIZE = 31;

    private static Film render(boolean schlick) {
        World world = new World(new ViewPlane(SIZE, SIZE, 1, (n, rng, xs, ys) -> {
            xs[0] = 0.5;
            ys[0] = 0.5;
        }, 3, 1), new Orthographic(new Point3D(0, 0, 10), Point3D.ORIGIN, Vector3D.UP, 2), new Ambient(0, RGBColor.WHITE));
        world.setBackground(RGBColor.WHITE);
        Sphere sphere = new Sphere(Point3D.ORIGIN, 1);
        sphere.setMaterial(new Reflective(0, 0, RGBColor.BLACK, 0, RGBColor.WHITE, 10, 0.5, new RGBColor(0.8, 0.5, 0.3), schlick));
        world.addObject(sphere);
        world.setTracer(Whitted::new);
        world.prepare();
        Film film = new Film(SIZE, SIZE);
        Renders.render(world, 1, 1, film);
        return film;
    }

    @Test
    void schlickMirrorReflectsMoreTowardsTheRim() {
        Film film = render(true);
        int inside = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                double px = (x + 0.5) / SIZE * 2 - 1;
                double py = 1 - (y + 0.5) / SIZE * 2;
                double r2 = px * px + py * py;
                if (r2 >= 0.98) {
                    continue; // silhouette pixels
                }
                inside++;
                double cos = Math.sqrt(1 - r2);
                double fraction = Fresnel.schlick(0.5, cos);
                assertEquals(0.8 * fraction, film.get(x, y, 0), 1e-6, "pixel " + x + "," + y);
                assertEquals(0.3 * fraction, film.get(x, y, 2), 1e-6);
            }
        }
        assertTrue(inside > 600);
        assertEquals(0.8 * 0.5, film.get(SIZE / 2, SIZE / 2, 0), 1e-3, "half at normal incidence");
    }

    @Test
    void withoutFresnelTheFractionIsConstant() {
        Film film = render(false);
        assertEquals(0.8 * 0.5, film.get(SIZE / 2, SIZE / 2, 0), 1e-6);
        assertEquals(0.8 * 0.5, film.get(SIZE / 2, 1, 0), 1e-6, "near the rim too");
    }
}

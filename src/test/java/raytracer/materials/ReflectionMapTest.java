package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.shapes.Sphere;
import raytracer.textures.EnvironmentMap;
import raytracer.tracers.Whitted;

/** A per-object reflection map replaces the scene's environment for that object's reflections only. */
class ReflectionMapTest {

    @Test
    void eachMirrorSeesItsOwnEnvironment() {
        Film red = new Film(2, 1);
        red.set(0, 0, 1, 0, 0);
        red.set(1, 0, 1, 0, 0);
        World world = new World(new ViewPlane(30, 10, 1, (n, rng, xs, ys) -> {
            xs[0] = 0.5;
            ys[0] = 0.5;
        }, 3, 1), new Orthographic(new Point3D(0, 0, 10), Point3D.ORIGIN, Vector3D.UP, 2), new Ambient(0, RGBColor.WHITE));
        world.setBackground(new RGBColor(0, 0, 1));
        Reflective own = new Reflective(0, 0, RGBColor.BLACK, 0, RGBColor.WHITE, 10, 1, RGBColor.WHITE, false);
        own.setReflectionMap(new EnvironmentMap(red, 1));
        Reflective plain = new Reflective(0, 0, RGBColor.BLACK, 0, RGBColor.WHITE, 10, 1, RGBColor.WHITE, false);
        Sphere left = new Sphere(new Point3D(-2, 0, 0), 0.9);
        left.setMaterial(own);
        Sphere right = new Sphere(new Point3D(2, 0, 0), 0.9);
        right.setMaterial(plain);
        world.addObject(left);
        world.addObject(right);
        world.setTracer(Whitted::new);
        world.prepare();
        Film film = new Film(30, 10);
        Renders.render(world, 1, 1, film);
        // centre of the left sphere: its reflection escapes into its own (red) map
        assertEquals(1, film.get(5, 5, 0), 1e-6);
        assertEquals(0, film.get(5, 5, 2), 1e-6);
        // the right sphere and the background see the scene's blue
        assertEquals(1, film.get(25, 5, 2), 1e-6);
        assertEquals(0, film.get(25, 5, 0), 1e-6);
        assertEquals(1, film.get(15, 5, 2), 1e-6);
    }
}

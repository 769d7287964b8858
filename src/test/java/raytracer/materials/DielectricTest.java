package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.cameras.Pinhole;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.Sampler;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.RenderStats;
import raytracer.render.Renders;
import raytracer.shapes.Box;
import raytracer.shapes.Sphere;
import raytracer.tracers.Whitted;

/** Glass against closed forms: the Fresnel series of normal incidence and Beer's law. */
class DielectricTest {
    private static final Sampler CENTRE = (n, rng, xs, ys) -> {
        xs[0] = 0.5;
        ys[0] = 0.5;
    };
    private static final double R = 0.04; // ((1.5 - 1) / (1.5 + 1))^2
    private static final double T = 1 - R;

    private static Film render(Camera camera, int size, RGBColor background, GeometricObject... objects) {
        World world = new World(new ViewPlane(size, size, 1, CENTRE, 40, 1), camera, new Ambient(1, RGBColor.WHITE));
        world.setBackground(background);
        for (GeometricObject o : objects) {
            world.addObject(o);
        }
        world.setTracer(Whitted::new);
        world.prepare();
        Film film = new Film(size, size);
        RenderStats stats = Renders.render(world, 1, 1, film);
        assertEquals(0, stats.nonFiniteSamples());
        return film;
    }

    private static GeometricObject with(GeometricObject o, raytracer.core.Material m) {
        o.setMaterial(m);
        return o;
    }

    private static Camera lookingDownZ(double viewHeight) {
        return new Orthographic(new Point3D(0, 0, 10), Point3D.ORIGIN, Vector3D.UP, viewHeight);
    }

    @Test
    void aRayThroughTheCentreOfAGlassSphereGoesStraight() {
        // behind the glass, on the axis, a red sphere lit by ambient light alone: its radiance is (1, 0, 0)
        GeometricObject glass = with(new Sphere(Point3D.ORIGIN, 1), new Dielectric(1.5, RGBColor.BLACK, 0, 1));
        GeometricObject red = with(new Sphere(new Point3D(0, 0, -5), 0.5), new Matte(1, 0, new RGBColor(1, 0, 0)));
        Film film = render(lookingDownZ(4), 5, RGBColor.BLACK, glass, red);
        // transmitted twice, plus pairs of internal reflections: (1 - R)^2 / (1 - R^2)
        assertEquals(T * T / (1 - R * R), film.get(2, 2, 0), 1e-6);
        assertEquals(0, film.get(2, 2, 1), 0);
    }

    @Test
    void withoutAbsorptionReflectionPlusRefractionLoseNothing() {
        // in a white world every path ends in the background, so each pixel must be exactly 1
        GeometricObject glass = with(new Sphere(Point3D.ORIGIN, 1), new Dielectric(1.5, RGBColor.BLACK, 0, 1));
        int size = 41;
        Film film = render(lookingDownZ(2.2), size, RGBColor.WHITE, glass);
        int checked = 0;
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                double px = (x + 0.5) / size * 2.2 - 1.1;
                double py = 1.1 - (y + 0.5) / size * 2.2;
                double v = film.get(x, y, 1);
                assertTrue(v <= 1 + 1e-6 && v >= 0, "pixel " + x + "," + y + " = " + v);
                // within 0.8 of the axis incidence stays below 53 degrees, R below 0.1: R^40 vanishes
                if (px * px + py * py < 0.64) {
                    assertEquals(1, v, 1e-6, "pixel " + x + "," + y);
                    checked++;
                }
            }
        }
        assertTrue(checked > 500, "checked " + checked);
    }

    @Test
    void beersLawThroughASlabWithItsInternalReflections() {
        RGBColor sigma = new RGBColor(0.5, 1, 2);
        double d = 1;
        GeometricObject slab = with(new Box(new Point3D(-3, -3, -0.5), new Point3D(3, 3, 0.5)),
                                    new Dielectric(1.5, sigma, 0, 1));
        Film film = render(lookingDownZ(4), 5, RGBColor.WHITE, slab);
        double[] s = {sigma.r(), sigma.g(), sigma.b()};
        for (int c = 0; c < 3; c++) {
            double a = Math.exp(-s[c] * d);
            // reflected at once, or after 2k internal reflections; transmitted after 2k of them
            double reflected = R + T * T * R * a * a / (1 - R * R * a * a);
            double transmitted = T * T * a / (1 - R * R * a * a);
            assertEquals(reflected + transmitted, film.get(2, 2, c), 1e-6, "channel " + c);
        }
        assertTrue(film.get(2, 2, 2) < film.get(2, 2, 0), "blue is absorbed most");
    }

    @Test
    void aCameraInsideTheMediumSeesItsOwnAbsorption() {
        double radius = 2;
        double sigma = 0.3;
        GeometricObject sphere = with(new Sphere(Point3D.ORIGIN, radius),
                                      new Dielectric(1.5, RGBColor.gray(sigma), 0, 1));
        // from the centre every camera ray meets the surface head on
        Film film = render(new Pinhole(Point3D.ORIGIN, new Point3D(0, 0, -1), Vector3D.UP, 60), 5, RGBColor.WHITE, sphere);
        double a = Math.exp(-sigma * radius);
        // out through the wall, or back across the diameter (a^2) after a reflection, and so on
        double expected = a * T / (1 - R * a * a);
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 5; x++) {
                assertEquals(expected, film.get(x, y, 0), 1e-6, "pixel " + x + "," + y);
            }
        }
    }

    @Test
    void totalInternalReflectionLosesNothing() {
        // inside a glass cube, looking along (0.8, 0, 0.6): the z faces are met at 53 degrees, past the
        // critical angle asin(1 / 1.5) = 41.8, so all of it turns back; the x faces at 37 degrees let
        // most through. In a white world every path ends in the background: each pixel is exactly 1;
        // a dielectric that dropped totally reflected rays would lose the 11% the first x face reflects.
        GeometricObject cube = with(new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1)), new Dielectric(1.5, RGBColor.BLACK, 0, 1));
        Film film = render(new Pinhole(new Point3D(0, 0, -0.5), new Point3D(0.8, 0, 0.1), Vector3D.UP, 1), 3, RGBColor.WHITE, cube);
        for (int y = 0; y < 3; y++) {
            for (int x = 0; x < 3; x++) {
                assertEquals(1, film.get(x, y, 0), 1e-6, "pixel " + x + "," + y);
            }
        }
    }
}

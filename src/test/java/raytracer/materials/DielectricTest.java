package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cameras.Orthographic;
import raytracer.cameras.Pinhole;
import raytracer.core.Background;
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

/**
 * Glass against closed forms: the Fresnel series of normal incidence, Beer's law, and oblique
 * incidence from either side: the refracted ray along Snell's law carrying 1 - R, the mirror ray
 * carrying R (Hecht's angle forms, written out here), and total internal reflection from inside.
 */
class DielectricTest {
    private static final Sampler CENTRE = (n, rng, xs, ys) -> {
        xs[0] = 0.5;
        ys[0] = 0.5;
    };
    private static final double R = 0.04; // ((1.5 - 1) / (1.5 + 1))^2
    private static final double T = 1 - R;

    private static Film render(Camera camera, int size, RGBColor background, GeometricObject... objects) {
        return render(camera, size, (ray, out) -> out.set(background), objects);
    }

    private static Film render(Camera camera, int size, Background background, GeometricObject... objects) {
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

    /**
     * Fresnel reflectance of unpolarised light from the angles of incidence i and refraction t
     * (Hecht, Optics, eq. 4.42 and 4.43): R = (sin^2(i - t) / sin^2(i + t) + tan^2(i - t) / tan^2(i + t)) / 2,
     * the same whichever side the light comes from.
     */
    private static double hechtReflectance(double i, double t) {
        return 0.5 * (Math.pow(Math.sin(i - t) / Math.sin(i + t), 2) + Math.pow(Math.tan(i - t) / Math.tan(i + t), 2));
    }

    /** A point at distance 1 from the origin along the unit direction at {@code angle} from the y axis, towards +x, above or below. */
    private static Point3D along(double angle, boolean up) {
        return new Point3D(Math.sin(angle), up ? Math.cos(angle) : -Math.cos(angle), 0);
    }

    /** A speck radius 1e-4 that shows {@code color} (ambient light only), whatever the angle. */
    private static GeometricObject speck(Point3D at, RGBColor color) {
        return with(new Sphere(at, 1e-4), new Matte(1, 0, color));
    }

    /**
     * A slab of glass, ior 1.5, filling -10 &lt; y &lt; 0, and one camera ray that meets its top
     * face at the origin at {@code angle} from the normal, in the xy plane, coming from above
     * (outside) or from below (inside). A red speck sits 1 along the mirror direction and a green
     * one 1 along the refracted direction that Snell's law gives (when there is one), each 1e-4 in
     * radius, so each takes the light of its ray only if that ray leaves within 1e-4 of the law's
     * direction; light going anywhere else upwards meets a blue sky, downwards black.
     */
    private static Film oblique(double angle, boolean fromInside) {
        double eta = fromInside ? 1.5 : 1 / 1.5; // n_i / n_t
        double sinT = eta * Math.sin(angle);
        GeometricObject slab = with(new Box(new Point3D(-100, -10, -100), new Point3D(100, 0, 100)), new Dielectric(1.5, RGBColor.BLACK, 0, 1));
        // the camera ray comes down onto the face from above, or up onto it from below
        Point3D eye = fromInside ? new Point3D(-2 * Math.sin(angle), -2 * Math.cos(angle), 0)
            : new Point3D(-2 * Math.sin(angle), 2 * Math.cos(angle), 0);
        Camera camera = new Orthographic(eye, Point3D.ORIGIN, new Vector3D(0, 0, 1), 1e-3);
        GeometricObject mirrored = speck(along(angle, !fromInside), new RGBColor(1, 0, 0));
        Background sky = (ray, out) -> out.set(0, 0, ray.dy > 0 ? 1 : 0);
        if (sinT >= 1) {
            return render(camera, 1, sky, slab, mirrored);
        }
        GeometricObject refracted = speck(along(Math.asin(sinT), fromInside), new RGBColor(0, 1, 0));
        return render(camera, 1, sky, slab, mirrored, refracted);
    }

    @ParameterizedTest(name = "{0} degrees")
    @ValueSource(doubles = {30, 45, 60, 80})
    void anObliqueRayEnteringGlassSplitsAlongSnellsLawAndFresnel(double degrees) {
        double i = Math.toRadians(degrees);
        double t = Math.asin(Math.sin(i) / 1.5);
        double r = hechtReflectance(i, t);
        Film film = oblique(i, false);
        assertEquals(r, film.get(0, 0, 0), 1e-6, "reflected");
        assertEquals(1 - r, film.get(0, 0, 1), 1e-6, "refracted");
        assertEquals(0, film.get(0, 0, 2), 0, "light going elsewhere");
    }

    @ParameterizedTest(name = "{0} degrees")
    @ValueSource(doubles = {20, 30, 40})
    void anObliqueRayLeavingGlassSplitsAlongSnellsLawAndFresnel(double degrees) {
        double i = Math.toRadians(degrees);
        double t = Math.asin(1.5 * Math.sin(i));
        double r = hechtReflectance(i, t);
        Film film = oblique(i, true);
        assertEquals(r, film.get(0, 0, 0), 1e-6, "reflected");
        assertEquals(1 - r, film.get(0, 0, 1), 1e-6, "refracted");
        assertEquals(0, film.get(0, 0, 2), 0, "light going elsewhere");
    }

    /** Past the critical angle asin(1 / 1.5) = 41.8 degrees, from inside: all reflected, nothing leaves. */
    @ParameterizedTest(name = "{0} degrees")
    @ValueSource(doubles = {42, 45, 60, 85})
    void pastTheCriticalAngleEverythingIsReflectedInside(double degrees) {
        Film film = oblique(Math.toRadians(degrees), true);
        assertEquals(1, film.get(0, 0, 0), 1e-6, "reflected");
        assertEquals(0, film.get(0, 0, 1), 0);
        assertEquals(0, film.get(0, 0, 2), 0, "transmitted into the sky");
    }
}

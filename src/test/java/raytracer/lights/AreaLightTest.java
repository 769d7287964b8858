package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cameras.Orthographic;
import raytracer.core.Light;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.materials.Matte;
import raytracer.materials.Reflective;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;
import raytracer.render.RenderStats;
import raytracer.render.Renders;
import raytracer.samplers.MultiJittered;
import raytracer.shapes.Plane;
import raytracer.shapes.Rectangle;
import raytracer.tracers.AreaLighting;

/**
 * Area lights are unbiased: a white Lambertian floor (radiance = E / pi) under a light must average
 * to the analytic irradiance. 900 pixels looking at (almost) the same point give 900 independent
 * estimates, since each pixel draws its own samples.
 */
class AreaLightTest {
    private static final int SIZE = 30;

    /** Mean and standard error of the pixel values. */
    private static double[] estimate(Light light) {
        World world = new World(new ViewPlane(SIZE, SIZE, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1e-6), new Ambient(0, RGBColor.WHITE));
        Plane floor = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        floor.setMaterial(new Matte(0, 1, RGBColor.WHITE));
        world.addObject(floor);
        world.addLight(light);
        world.setTracer(AreaLighting::new);
        world.prepare();
        Film film = new Film(SIZE, SIZE);
        Renders.render(world, 2, 7, film);
        return meanAndError(film);
    }

    /** Mean and standard error of the red channel over the film's pixels. */
    private static double[] meanAndError(Film film) {
        double sum = 0;
        double sum2 = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                double v = film.get(x, y, 0);
                sum += v;
                sum2 += v * v;
            }
        }
        int n = SIZE * SIZE;
        double mean = sum / n;
        return new double[] {mean, Math.sqrt(Math.max(0, sum2 / n - mean * mean) / n)};
    }

    // Three lights over the origin with their analytic irradiance E at the origin (normal +y),
    // given as E / pi: the radiance of a white Lambertian floor there.

    /** On the axis of a disk: E = pi Le R^2 / (h^2 + R^2). */
    private static final double DISK_EXPECTED = 3.0 * 1 * 1 / (2 * 2 + 1 * 1);

    private static AreaLight disk(int samples) {
        return AreaLight.disk(new Point3D(0, 2, 0), new Vector3D(0, -1, 0), 1, 3, RGBColor.WHITE, samples);
    }

    /** A sphere wholly above the horizon, straight above: E = pi Le (R / d)^2. */
    private static final double SPHERE_EXPECTED = 2 * 0.5 * 0.5 / (3.0 * 3);

    private static AreaLight sphere(int samples) {
        return AreaLight.sphere(new Point3D(0, 3, 0), 0.5, 2, RGBColor.WHITE, samples);
    }

    /**
     * A 2a x 2b rectangle at height h, centred above: four corner rectangles a x b. The
     * configuration factor of a differential area to a parallel rectangle above one corner is
     * F = (X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) + Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))) / (2 pi),
     * X = a / h, Y = b / h, and E = pi Le 4 F.
     */
    private static final double RECTANGLE_EXPECTED = rectangleExpected(3, 1, 0.5, 2);

    private static double rectangleExpected(double le, double a, double b, double h) {
        double x = a / h;
        double y = b / h;
        double f = (x / Math.sqrt(1 + x * x) * Math.atan(y / Math.sqrt(1 + x * x))
                    + y / Math.sqrt(1 + y * y) * Math.atan(x / Math.sqrt(1 + y * y))) / (2 * Math.PI);
        return le * 4 * f;
    }

    private static AreaLight rectangle(int samples) {
        return AreaLight.rectangle(new Point3D(-1, 2, -0.5), new Vector3D(2, 0, 0), new Vector3D(0, 0, 1), 3, RGBColor.WHITE, samples);
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 16})
    void diskLightMatchesTheAnalyticIrradiance(int samples) {
        double[] e = estimate(disk(samples));
        assertEquals(DISK_EXPECTED, e[0], 4 * e[1] + 1e-6, samples + " samples: mean " + e[0] + " +- " + e[1]);
        assertTrue(e[1] < 0.02 * DISK_EXPECTED, "the estimate should be reasonably precise: " + e[1]);
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 16})
    void sphereLightMatchesTheAnalyticIrradiance(int samples) {
        double[] e = estimate(sphere(samples));
        assertEquals(SPHERE_EXPECTED, e[0], 4 * e[1] + 1e-6, samples + " samples: mean " + e[0] + " +- " + e[1]);
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 16})
    void rectangleLightMatchesTheAnalyticIrradiance(int samples) {
        double[] e = estimate(rectangle(samples));
        assertEquals(RECTANGLE_EXPECTED, e[0], 4 * e[1] + 1e-6, samples + " samples: mean " + e[0] + " +- " + e[1]);
        assertTrue(e[1] < 0.02 * RECTANGLE_EXPECTED, "the estimate should be reasonably precise: " + e[1]);
    }

    /**
     * Close up, where sampling by solid angle differs most from sampling by area: a sphere of
     * radius 1 whose lowest point is 0.1 above the floor (E = pi Le (R / d)^2 still, the sphere
     * being wholly above the horizon) and the 2 x 1 rectangle 0.25 above it, one sample each.
     */
    @ParameterizedTest
    @ValueSource(strings = {"sphere", "rectangle"})
    void closeLightsMatchTheAnalyticIrradiance(String kind) {
        boolean sphere = kind.equals("sphere");
        AreaLight light = sphere ? AreaLight.sphere(new Point3D(0, 1.1, 0), 1, 2, RGBColor.WHITE, 1)
            : AreaLight.rectangle(new Point3D(-1, 0.25, -0.5), new Vector3D(2, 0, 0), new Vector3D(0, 0, 1), 3, RGBColor.WHITE, 1);
        double expected = sphere ? 2 / (1.1 * 1.1) : rectangleExpected(3, 1, 0.5, 0.25);
        double[] e = estimate(light);
        assertEquals(expected, e[0], 4 * e[1] + 1e-6, kind + ": mean " + e[0] + " +- " + e[1]);
        assertTrue(e[1] < 0.02 * expected, "the estimate should be reasonably precise: " + e[1]);
    }

    /**
     * The book's estimator without a render: the mean over a fine stratified grid of samples of
     * Le G cos(theta_i) / pdf, from the light's own sample, G and pdf, is the irradiance; and pdf is
     * the density of the light's sampling, computed here independently: 1 / area for the disk
     * (area pi R^2); G / Omega for the sphere, sampled uniformly over the solid angle
     * Omega = 2 pi (1 - sqrt(1 - (R / D)^2)) it covers D away, and for the 2 x 1 rectangle 2 and
     * 0.25 above, over its Omega = 4 asin(a b / sqrt((a^2 + h^2)(b^2 + h^2))), a 2a x 2b rectangle
     * centred h above.
     */
    @ParameterizedTest
    @ValueSource(strings = {"disk", "sphere", "rectangle", "near rectangle"})
    void gOverPdfAveragesToTheAnalyticIrradiance(String kind) {
        double h = kind.equals("near rectangle") ? 0.25 : 2;
        AreaLight light = kind.equals("disk") ? disk(1) : kind.equals("sphere") ? sphere(1)
            : AreaLight.rectangle(new Point3D(-1, h, -0.5), new Vector3D(2, 0, 0), new Vector3D(0, 0, 1), 3, RGBColor.WHITE, 1);
        double expected = kind.equals("disk") ? DISK_EXPECTED : kind.equals("sphere") ? SPHERE_EXPECTED : rectangleExpected(3, 1, 0.5, h);
        double solidAngle = kind.equals("sphere") ? 2 * Math.PI * (1 - Math.sqrt(1 - 0.5 * 0.5 / (3.0 * 3)))
            : 4 * Math.asin(1 * 0.5 / Math.sqrt((1 + h * h) * (0.5 * 0.5 + h * h)));
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.hitPoint.set(0, 0, 0);
        sr.normal.set(0, 1, 0);
        MutableRgb le = new MutableRgb();
        MutableVec3 wi = new MutableVec3();
        int grid = 400;
        double sum = 0;
        for (int i = 0; i < grid; i++) {
            for (int j = 0; j < grid; j++) {
                light.sample(sr, (i + 0.5) / grid, (j + 0.5) / grid, wi);
                double pdf = kind.equals("disk") ? 1 / Math.PI : light.G(sr) / solidAngle;
                assertEquals(pdf, light.pdf(sr), 1e-12 * pdf, kind + ": the sampling's density");
                light.L(sr, le);
                double cos = Math.max(0, sr.normal.dot(wi));
                sum += le.r * light.G(sr) * cos / light.pdf(sr);
            }
        }
        assertEquals(expected, sum / (grid * grid) / Math.PI, 1e-4 * expected, kind);
    }

    /** G = cos(theta_light) / d^2 where both are known: the disk's centre and a point of its rim. */
    @Test
    void gIsTheCosineAtTheLightOverTheSquaredDistance() {
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.hitPoint.set(0, 0, 0);
        MutableVec3 wi = new MutableVec3();
        AreaLight light = disk(1);
        // the concentric map sends (0.5, 0.5) to the centre, straight above at h = 2
        assertEquals(2, light.sample(sr, 0.5, 0.5, wi), 1e-12);
        assertEquals(1 / 4.0, light.G(sr), 1e-12);
        // (1, 0.5) goes to the rim, at distance sqrt(5) and cos(theta_light) = 2 / sqrt(5)
        assertEquals(Math.sqrt(5), light.sample(sr, 1, 0.5, wi), 1e-12);
        assertEquals(2 / Math.sqrt(5) / 5, light.G(sr), 1e-12);
        // from above the disk, which emits downwards, nothing
        sr.hitPoint.set(0, 3, 0);
        light.sample(sr, 0.5, 0.5, wi);
        assertEquals(0, light.G(sr));
    }

    @ParameterizedTest
    @ValueSource(ints = {16})
    void rectangleLightFacingAwayGivesNothing(int samples) {
        // emitting upwards from above the floor: the floor sees only its back
        double[] e = estimate(AreaLight.rectangle(new Point3D(-1, 2, -1), new Vector3D(0, 0, 2), new Vector3D(2, 0, 0),
                                                  5, RGBColor.WHITE, samples));
        assertEquals(0, e[0], 0);
        double[] facing = estimate(AreaLight.rectangle(new Point3D(-1, 2, -1), new Vector3D(2, 0, 0), new Vector3D(0, 0, 2),
                                                       5, RGBColor.WHITE, samples));
        assertTrue(facing[0] > 0.5, "facing down it lights the floor: " + facing[0]);
    }

    /**
     * An emitter that says it cannot light a point must be right: no sample of it may then be both
     * in front of its emitting side and above the point's tangent plane. Checked on random points
     * and normals around each kind of emitter, with 400 samples each.
     */
    @Test
    void emittersThatSayTheyCannotLightAPointNeverDo() {
        Emitter[] emitters = {
            new RectangleEmitter(new Point3D(-1, 2, -0.5), new Vector3D(2, 0, 0.3), new Vector3D(0.2, 0, 1)),
            new DiskEmitter(new Point3D(0.5, 1, 0), new Vector3D(1, -2, 0.5), 0.7),
            new SphereEmitter(new Point3D(0, 1.5, 0.5), 0.6)};
        SplittableRandom random = new SplittableRandom(5);
        MutableVec3 p = new MutableVec3();
        MutableVec3 n = new MutableVec3();
        MutableVec3 q = new MutableVec3();
        MutableVec3 qn = new MutableVec3();
        for (Emitter e : emitters) {
            int refused = 0;
            for (int i = 0; i < 20_000; i++) {
                p.set(random.nextDouble(-4, 4), random.nextDouble(-4, 4), random.nextDouble(-4, 4));
                n.set(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1)).normalize();
                boolean may = e.mayLight(p, n);
                boolean lit = false;
                for (int s = 0; s < 400 && !lit; s++) {
                    e.sample(p, (s % 20 + 0.5) / 20, (s / 20 + 0.5) / 20, q, qn);
                    double dx = q.x - p.x;
                    double dy = q.y - p.y;
                    double dz = q.z - p.z;
                    lit = n.dot(dx, dy, dz) > 0 && -qn.dot(dx, dy, dz) > 0;
                }
                if (!may) {
                    refused++;
                    assertTrue(!lit, e.getClass().getSimpleName() + " refused a point it lights");
                }
            }
            assertTrue(refused > 2000, e.getClass().getSimpleName() + " should refuse many points: " + refused);
        }
    }

    /**
     * With the cutoff on, a hit seen in a mirror of reflectance 0.3 takes floor(16 x 0.3) = 4 light
     * samples instead of 16: fewer shadow rays, still the analytic irradiance.
     * The camera looks down -z at a 45-degree mirror that sends its rays straight down to the floor.
     */
    @Test
    void hitsSeenInAMirrorTakeFewerSamplesAndStayUnbiased() {
        double le = 3;
        double radius = 1;
        double height = 1.5;
        double kr = 0.3;
        double expected = kr * le * radius * radius / (height * height + radius * radius);
        double[] cutoffs = {0, 1e-3};
        long[] shadowRays = new long[2];
        for (int k = 0; k < 2; k++) {
            World world = new World(new ViewPlane(SIZE, SIZE, 1, new MultiJittered(), 1, 1),
                new Orthographic(new Point3D(0, 0, 5), Point3D.ORIGIN, Vector3D.UP, 1e-6), new Ambient(0, RGBColor.WHITE));
            Rectangle mirror = new Rectangle(new Point3D(-1, -1, -1), new Vector3D(2, 0, 0), new Vector3D(0, 2, 2));
            mirror.setMaterial(new Reflective(0, 0, RGBColor.BLACK, 0, RGBColor.WHITE, 1, kr, RGBColor.WHITE, false));
            world.addObject(mirror);
            Plane floor = new Plane(new Point3D(0, -3, 0), new Normal(0, 1, 0));
            floor.setMaterial(new Matte(0, 1, RGBColor.WHITE));
            world.addObject(floor);
            world.addLight(AreaLight.disk(new Point3D(0, -3 + height, 0), new Vector3D(0, -1, 0), radius, le, RGBColor.WHITE, 16));
            world.setTracer(AreaLighting::new);
            world.prepare();
            Film film = new Film(SIZE, SIZE);
            RenderStats stats = Renders.render(world, RayTreeSettings.FULL_TREE.withCutoff(cutoffs[k]), 2, 7, film);
            shadowRays[k] = stats.shadowRays();
            double[] estimate = meanAndError(film);
            double mean = estimate[0];
            double error = estimate[1];
            assertEquals(expected, mean, 4 * error + 1e-6, "cutoff " + cutoffs[k] + ": mean " + mean + " +- " + error);
        }
        assertEquals(16L * SIZE * SIZE, shadowRays[0]);
        assertEquals(4L * SIZE * SIZE, shadowRays[1]);
    }

    /** Whether a point with these shading and geometric normals sees a square light above it that emits downwards. */
    private static boolean mayIlluminate(double[] normal, double[] geometric) {
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.hitPoint.set(0, 0, 0);
        sr.normal.set(normal[0], normal[1], normal[2]);
        sr.geometricNormal.set(geometric[0], geometric[1], geometric[2]);
        AreaLight light = AreaLight.rectangle(new Point3D(-1, 4, -1), new Vector3D(2, 0, 0), new Vector3D(0, 0, 2), 1,
                                              RGBColor.WHITE, 1);
        return light.mayIlluminate(sr);
    }

    @Test
    void aLightMayIlluminateAPointOnlyWhenBothItsNormalsSeeIt() {
        double[] up = {0, 1, 0};
        double[] down = {0, -1, 0};
        double[] tilted = {0.6, 0.8, 0};
        assertTrue(mayIlluminate(up, up));
        assertTrue(mayIlluminate(tilted, up));
        assertFalse(mayIlluminate(down, down));
        assertFalse(mayIlluminate(up, down), "a shading normal that sees the light does not answer for the geometric one");
        assertFalse(mayIlluminate(down, up));
    }
}

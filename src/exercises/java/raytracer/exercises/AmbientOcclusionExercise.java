package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.GeometricObject;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.Vector3D;
import raytracer.shapes.Disk;
import raytracer.shapes.Sphere;

/**
 * Exercise 4: ambient occlusion (Suffern, chapter 17), an ambient light whose radiance ls c is
 * scaled by the fraction of the hemisphere above the hit that is open, each of {@code samples}
 * directions drawn with density cos(theta) / pi about the normal and tested with a shadow ray.
 * Checked against the configuration factor of a disk above the point: a parallel coaxial disk of
 * radius R at height h covers R^2 / (R^2 + h^2) of the cosine-weighted hemisphere.
 */
@Tag("exercise")
class AmbientOcclusionExercise {
    private static Constructor<? extends Light> occluder;
    private static final RGBColor COLOR = new RGBColor(1, 0.9, 0.8);

    @BeforeAll
    static void findTheClass() {
        occluder = Student.constructor(4, "raytracer.lights.AmbientOccluder", Light.class, double.class, RGBColor.class, int.class);
    }

    private static Light occluder(int samples) {
        return Student.create(occluder, 0.5, COLOR, samples);
    }

    /** The mean green radiance over {@code calls} shadings of the point at the origin with normal (nx, ny, nz). */
    private static double meanRadiance(Light light, int calls, double nx, double ny, double nz, GeometricObject... objects) {
        Scratch scratch = new Scratch(objects);
        MutableRgb out = new MutableRgb();
        double sum = 0;
        for (int call = 0; call < calls; call++) {
            // the renderer reseeds the worker's generator for every pixel sample
            scratch.worker.rng.reseed(call);
            ShadeRec sr = scratch.surfacePoint(0, 0, 0, nx, ny, nz);
            light.L(sr, out);
            sum += out.g;
        }
        return sum / calls;
    }

    @Test
    void underAnOpenSkyItIsTheAmbientLight() {
        assertEquals(0.5 * COLOR.g(), meanRadiance(occluder(16), 10, 0, 1, 0), 1e-15,
                     "AmbientOccluder(0.5, " + COLOR + ", 16), nothing around: every direction is open, so L = ls c exactly");
    }

    @Test
    void aDiskAboveHidesItsConfigurationFactor() {
        double[][] cases = {{1, 1}, {1, 2}, {2, 1}};
        for (double[] c : cases) {
            double radius = c[0];
            double height = c[1];
            Disk disk = new Disk(new Point3D(0, height, 0), new Vector3D(0, -1, 0), radius);
            double open = 1 - radius * radius / (radius * radius + height * height);
            // 300 x 64 samples: a standard error below 0.004 of the fraction
            double got = meanRadiance(occluder(64), 300, 0, 1, 0, disk) / (0.5 * COLOR.g());
            assertEquals(open, got, 0.02, "a disk of radius " + radius + " at height " + height
                                          + ": is the hemisphere sampled with density cos(theta) / pi around the normal?");
        }
    }

    @Test
    void directionsFollowTheNormal() {
        // the same disk, but the surface faces down and away from it: nothing is hidden
        Disk disk = new Disk(new Point3D(0, 1, 0), new Vector3D(0, -1, 0), 1);
        assertEquals(0.5 * COLOR.g(), meanRadiance(occluder(64), 20, 0, -1, 0, disk), 1e-15,
                     "a point facing down, a disk of radius 1 at height 1 above it: its hemisphere is open, so L = ls c exactly "
                     + "(directions must be drawn about sr.normal)");
        // facing sideways, exactly the upper half of the hemisphere meets a large disk just above
        Disk large = new Disk(new Point3D(0, 1e-3, 0), new Vector3D(0, -1, 0), 1e4);
        assertEquals(0.5, meanRadiance(occluder(64), 300, 1, 0, 0, large) / (0.5 * COLOR.g()), 0.02,
                     "a point facing +x under a disk of radius 1e4 just above it: the upper half of its hemisphere is hidden, "
                     + "so L must be ls c / 2 (to 0.02)");
    }

    @Test
    void insideAClosedSphereEverythingIsHidden() {
        assertEquals(0, meanRadiance(occluder(32), 10, 0, 1, 0, new Sphere(new Point3D(0, 0, 0), 1)), 1e-15,
                     "the centre of a closed sphere of radius 1: every shadow ray is blocked, so L = 0");
    }

    @Test
    void theSameGeneratorGivesTheSameAnswer() {
        Disk disk = new Disk(new Point3D(0, 1, 0), new Vector3D(0, -1, 0), 1);
        Light light = occluder(8);
        assertEquals(meanRadiance(light, 5, 0, 1, 0, disk), meanRadiance(light, 5, 0, 1, 0, disk), 0,
                     "random numbers come from sr.scratch.rng, which the renderer seeds per pixel");
    }

    @Test
    void atLeastOneSampleIsNeeded() {
        assertThrows(IllegalArgumentException.class, () -> occluder(0),
                     "AmbientOccluder(0.5, c, 0): at least one sample is needed (IllegalArgumentException)");
    }

    @Test
    void itCastsShadows() {
        assertTrue(occluder(8).castsShadows(), "castsShadows() must stay true (the default): the scene analysis keeps the "
                                               + "objects that could shadow a light that casts shadows, and this one's rays go "
                                               + "everywhere (docs/teaching.md, exercise 4)");
    }
}

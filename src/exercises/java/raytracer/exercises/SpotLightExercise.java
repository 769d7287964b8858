package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.lights.PointLight;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * Exercise 3: a spot light, a point light (Suffern, chapter 14) that shines only into a cone
 * around its direction: as the point light within falloffStart degrees of the axis, nothing
 * beyond totalAngle degrees, and in between the point light's value times
 * ((cos(theta) - cos(total)) / (cos(start) - cos(total)))^4 (pbrt-v3, section 12.2.1). Checked
 * against the project's PointLight and that closed form.
 */
@Tag("exercise")
class SpotLightExercise {
    private static Constructor<? extends Light> spot;
    private static final Point3D POSITION = new Point3D(1, 4, -2);
    private static final RGBColor COLOR = new RGBColor(1, 0.8, 0.5);

    private final Scratch scratch = new Scratch();

    @BeforeAll
    static void findTheClass() {
        spot = Student.constructor(3, "raytracer.lights.SpotLight", Light.class, double.class, RGBColor.class, Point3D.class,
                                   Vector3D.class, double.class, double.class);
    }

    private static Light spot(Vector3D direction, double total, double start) {
        return Student.create(spot, 30.0, COLOR, POSITION, direction, total, start);
    }

    /** A surface point at angle theta (degrees) from the downward axis, at distance r from the light. */
    private ShadeRec pointAt(double thetaDegrees, double phiDegrees, double r) {
        double theta = Math.toRadians(thetaDegrees);
        double phi = Math.toRadians(phiDegrees);
        double x = POSITION.x() + r * Math.sin(theta) * Math.cos(phi);
        double y = POSITION.y() - r * Math.cos(theta);
        double z = POSITION.z() + r * Math.sin(theta) * Math.sin(phi);
        return scratch.surfacePoint(x, y, z, 0, 1, 0);
    }

    private static MutableRgb radiance(Light light, ShadeRec sr) {
        MutableRgb out = new MutableRgb();
        light.L(sr, out);
        return out;
    }

    @Test
    void withinTheInnerConeItIsThePointLight() {
        Light spot = spot(new Vector3D(0, -1, 0), 40, 25);
        Light point = new PointLight(30.0, COLOR, POSITION);
        SplittableRandom random = new SplittableRandom(9);
        MutableVec3 fromSpot = new MutableVec3();
        MutableVec3 fromPoint = new MutableVec3();
        for (int i = 0; i < 1000; i++) {
            double theta = 25 * random.nextDouble();
            double phi = 360 * random.nextDouble();
            double r = 0.1 + 10 * random.nextDouble();
            ShadeRec sr = pointAt(theta, phi, r);
            String where = "SpotLight(30, " + COLOR + ", " + POSITION + ", down, total 40, start 25) at " + theta
                           + " degrees from the axis (azimuth " + phi + "), " + r + " away: ";
            MutableRgb expected = radiance(point, sr);
            MutableRgb got = radiance(spot, sr);
            assertEquals(expected.r, got.r, 1e-12 * expected.r, where + "within the inner cone L must be the point light's I / r^2, red");
            assertEquals(expected.b, got.b, 1e-12 * expected.b, where + "within the inner cone L must be the point light's I / r^2, blue");
            double d = spot.getDirection(sr, fromSpot);
            assertEquals(point.getDirection(sr, fromPoint), d, 1e-12 * d, where + "getDirection must return the distance to the light");
            String direction = where + "getDirection must write the unit direction to the light, " + fromPoint + ", got " + fromSpot;
            assertEquals(0, fromSpot.x - fromPoint.x, 1e-12, direction);
            assertEquals(0, fromSpot.y - fromPoint.y, 1e-12, direction);
            assertEquals(0, fromSpot.z - fromPoint.z, 1e-12, direction);
        }
    }

    @Test
    void beyondTheConeItIsDark() {
        Light spot = spot(new Vector3D(0, -1, 0), 40, 25);
        for (double theta : new double[] {40.01, 60, 90, 135, 180}) {
            MutableRgb got = radiance(spot, pointAt(theta, 17, 3));
            assertTrue(got.isBlack(), "SpotLight(..., down, total 40, start 25) at " + theta
                                      + " degrees from the axis, beyond the cone: L must be black, got " + got);
        }
    }

    @Test
    void betweenTheConesItFallsOffAsTheFourthPowerOfTheCosineRatio() {
        Light spot = spot(new Vector3D(0, -1, 0), 40, 25);
        double cosTotal = Math.cos(Math.toRadians(40));
        double cosStart = Math.cos(Math.toRadians(25));
        for (double theta : new double[] {26, 30, 35, 39}) {
            double r = 2.5;
            double ratio = (Math.cos(Math.toRadians(theta)) - cosTotal) / (cosStart - cosTotal);
            double expected = 30 * COLOR.g() / (r * r) * Math.pow(ratio, 4);
            assertEquals(expected, radiance(spot, pointAt(theta, 200, r)).g, 1e-9 * expected,
                         "SpotLight(30, ..., down, total 40, start 25) at " + theta + " degrees from the axis, " + r
                         + " away: L must be I / r^2 ((cos(theta) - cos(total)) / (cos(start) - cos(total)))^4, green");
        }
    }

    @Test
    void theDirectionNeedNotBeUnitAndMayPointAnywhere() {
        Light longAxis = spot(new Vector3D(0, -5, 0), 30, 10);
        ShadeRec sr = pointAt(20, 0, 2);
        double ratio = (Math.cos(Math.toRadians(20)) - Math.cos(Math.toRadians(30)))
                       / (Math.cos(Math.toRadians(10)) - Math.cos(Math.toRadians(30)));
        assertEquals(30 * COLOR.r() / 4 * Math.pow(ratio, 4), radiance(longAxis, sr).r, 1e-9,
                     "SpotLight(..., direction (0, -5, 0), total 30, start 10) at 20 degrees, 2 away: a direction of length 5 "
                     + "is the same axis as (0, -1, 0)");
        // a spot pointing along +x lights a point on the +x side, not one below it
        Light sideways = spot(new Vector3D(1, 0, 0), 30, 10);
        assertEquals(30 * COLOR.r() / 9, radiance(sideways, scratch.surfacePoint(POSITION.x() + 3, POSITION.y(), POSITION.z(), -1, 0, 0)).r,
                     1e-12, "SpotLight(..., direction (1, 0, 0)): a point 3 along +x from the light lies on its axis, L = I / 9");
        assertTrue(radiance(sideways, pointAt(0, 0, 3)).isBlack(),
                   "SpotLight(..., direction (1, 0, 0), total 30): a point 3 below the light is 90 degrees off its axis, L = 0");
    }

    @Test
    void itCastsShadowsLikeEveryLight() {
        assertTrue(spot(new Vector3D(0, -1, 0), 40, 25).castsShadows(), "castsShadows() must be true, as for every light by default");
    }

    @Test
    void impossibleConesAreRefused() {
        Vector3D down = new Vector3D(0, -1, 0);
        String rule = ": 0 <= start <= total < 180 and total > 0, else IllegalArgumentException";
        assertThrows(IllegalArgumentException.class, () -> spot(down, 20, 30), "total 20, start 30: the falloff cannot start outside the cone" + rule);
        assertThrows(IllegalArgumentException.class, () -> spot(down, 0, 0), "total 0, start 0" + rule);
        assertThrows(IllegalArgumentException.class, () -> spot(down, 180, 10), "total 180, start 10" + rule);
        assertThrows(IllegalArgumentException.class, () -> spot(down, 30, -1), "total 30, start -1" + rule);
        assertThrows(IllegalArgumentException.class, () -> spot(new Vector3D(0, 0, 0), 30, 10),
                     "direction (0, 0, 0): a direction of length 0 has no axis (IllegalArgumentException)");
    }
}

package raytracer.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.image.Film;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** The exact image: where each film point lands, what a pixel holds, how accurate its quadrature is. */
class LitPlaneTest {
    private static final ExactLight LIGHT = PolygonLight.rectangle(new Point3D(-1.5, 1.5, -0.5), new Vector3D(2, 0, 0),
                                                                   new Vector3D(0, 0, 1));

    /** Looking straight down from y = 3 with up = -z: image right is +x, image top is -z. */
    private static LitPlane scene(int width, int height, RGBColor ambient, double exposure) {
        return new LitPlane(width, height, new Point3D(0, 3, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 4,
                            Point3D.ORIGIN, Vector3D.UP, new RGBColor(0.8, 0.6, 0.4), ambient, RGBColor.gray(5), LIGHT, exposure);
    }

    @Test
    void filmPointsLandWhereTheCameraFrameSays() {
        // 4 x 2 pixels, view 4 high and 8 wide: the film's top left corner is the floor point (-4, 0, -2),
        // its bottom right (4, 0, 2), and film point (3, 0.5) is (2, 0, -1)
        LitPlane plane = scene(4, 2, RGBColor.BLACK, 1);
        LitPlane.View view = LitPlane.View.of(plane.eye(), plane.lookAt(), plane.up(), plane.viewHeight(), 4, 2);
        double[][] film = {{0, 0}, {4, 2}, {3, 0.5}};
        double[][] floor = {{-4, -2}, {4, 2}, {2, -1}};
        for (int i = 0; i < film.length; i++) {
            double expected = LIGHT.projectedSolidAngle(floor[i][0], 0, floor[i][1], 0, 1, 0);
            assertEquals(expected, plane.projectedSolidAngleAt(film[i][0], film[i][1], view), 1e-15, "film point " + i);
            Point3D origin = view.origin(film[i][0], film[i][1]);
            assertEquals(floor[i][0], origin.x(), 1e-15);
            assertEquals(floor[i][1], origin.z(), 1e-15);
        }
    }

    @Test
    void aPixelHoldsAmbientPlusAlbedoOverPiTimesIrradiance() {
        LitPlane plane = scene(8, 6, new RGBColor(0.01, 0.02, 0.03), 2);
        Film film = plane.render(4);
        LitPlane.View view = LitPlane.View.of(plane.eye(), plane.lookAt(), plane.up(), plane.viewHeight(), 8, 6);
        double omega = plane.pixelProjectedSolidAngle(5, 2, new GaussLegendre(4), view);
        assertEquals(2 * (0.01 + 0.8 / Math.PI * 5 * omega), film.get(5, 2, 0), 1e-6);
        assertEquals(2 * (0.03 + 0.4 / Math.PI * 5 * omega), film.get(5, 2, 2), 1e-6);
        // with no light, the ambient term alone, everywhere
        LitPlane dark = new LitPlane(8, 6, plane.eye(), plane.lookAt(), plane.up(), 4, Point3D.ORIGIN, Vector3D.UP,
                                     RGBColor.gray(0.8), RGBColor.gray(0.25), RGBColor.BLACK, LIGHT, 1);
        Film ambient = dark.render(2);
        for (int y = 0; y < 6; y++) {
            for (int x = 0; x < 8; x++) {
                assertEquals(0.25, ambient.get(x, y, 1), 0);
            }
        }
    }

    /**
     * The quadrature's own error on this scene at 64 x 64 pixels, in double precision: the 8 x 8 rule
     * against the 16 x 16 one, relative to the mean. Measured: at most 6e-15 (rounding), and 4e-15 for
     * the 4 x 4 rule; a single midpoint per pixel is off by up to 8.5e-4: a pixel's average is not
     * its centre's value.
     */
    @Test
    void eightByEightGaussLegendreIsExactToRoundingOnThisScene() {
        LitPlane plane = scene(64, 64, RGBColor.BLACK, 1);
        LitPlane.View view = LitPlane.View.of(plane.eye(), plane.lookAt(), plane.up(), plane.viewHeight(), 64, 64);
        GaussLegendre[] rules = {new GaussLegendre(1), new GaussLegendre(4), new GaussLegendre(8), new GaussLegendre(16)};
        double[] worst = new double[3];
        double mean = 0;
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 64; x++) {
                double fine = plane.pixelProjectedSolidAngle(x, y, rules[3], view);
                mean += fine / (64 * 64);
                for (int r = 0; r < 3; r++) {
                    worst[r] = Math.max(worst[r], Math.abs(plane.pixelProjectedSolidAngle(x, y, rules[r], view) - fine));
                }
            }
        }
        assertTrue(worst[2] < 1e-13 * mean, "8x8 against 16x16: " + worst[2] / mean);
        assertTrue(worst[1] < 1e-10 * mean, "4x4 against 16x16: " + worst[1] / mean);
        assertTrue(worst[0] > 1e-5 * mean, "the centre value should differ from the average: " + worst[0] / mean);
    }

    @Test
    void scenesWithoutAnExactImageAreRefused() {
        Point3D eye = new Point3D(0, 3, 0);
        Vector3D up = new Vector3D(0, 0, -1);
        RGBColor grey = RGBColor.gray(0.5);
        // the camera looks at the plane's back
        assertThrows(IllegalArgumentException.class, () -> new LitPlane(8, 8, eye, Point3D.ORIGIN, up, 4, Point3D.ORIGIN,
            new Vector3D(0, -1, 0), grey, grey, grey, LIGHT, 1));
        // the light reaches below the plane
        assertThrows(IllegalArgumentException.class, () -> new LitPlane(8, 8, eye, Point3D.ORIGIN, up, 4, new Point3D(0, 1.5, 0),
            Vector3D.UP, grey, grey, grey, LIGHT, 1));
        // the camera's window is below the plane
        assertThrows(IllegalArgumentException.class, () -> new LitPlane(8, 8, new Point3D(0, -1, 0), new Point3D(0, -2, 0), up, 4,
            Point3D.ORIGIN, Vector3D.UP, grey, grey, grey, LIGHT, 1));
        // up along the view
        assertThrows(IllegalArgumentException.class, () -> new LitPlane(8, 8, eye, Point3D.ORIGIN, Vector3D.UP, 4, Point3D.ORIGIN,
            Vector3D.UP, grey, grey, grey, LIGHT, 1));
    }
}

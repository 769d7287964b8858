package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.lang.reflect.Constructor;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.Camera;
import raytracer.core.ViewPlane;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.samplers.Regular;

/**
 * Exercise 2: the spherical panoramic camera (Suffern, chapter 11). The image's x runs through
 * the azimuth lambda in [-h/2, h/2] and its y through the elevation psi in [-v/2, v/2] (h and v
 * the horizontal and vertical fields of view), and the pixel's ray from the eye is
 * cos(psi) sin(lambda) u + sin(psi) v - cos(psi) cos(lambda) w in the camera's frame (u right,
 * v up, w from the look-at point back to the eye, as in Suffern, section 9.2). Checked against
 * that closed form and at points where the answer is plain.
 */
@Tag("exercise")
class SphericalCameraExercise {
    private static final Point3D EYE = new Point3D(1, 2, 3);
    private static final Point3D LOOK_AT = new Point3D(0, 1, -2);
    private static final int WIDTH = 400;
    private static final int HEIGHT = 200;
    private static Constructor<? extends Camera> spherical;

    private final ViewPlane viewPlane = new ViewPlane(WIDTH, HEIGHT, 1, new Regular(), 2, 1);
    // the camera's frame, computed here
    private final Vector3D w = EYE.sub(LOOK_AT).normalize();
    private final Vector3D u = Vector3D.UP.cross(w).normalize();
    private final Vector3D v = w.cross(u);

    @BeforeAll
    static void findTheClass() {
        spherical = Student.constructor(2, "raytracer.cameras.Spherical", Camera.class, Point3D.class, Point3D.class,
                                        Vector3D.class, double.class, double.class);
    }

    private static Camera camera(double horizontal, double vertical) {
        return Student.create(spherical, EYE, LOOK_AT, Vector3D.UP, horizontal, vertical);
    }

    private Ray ray(Camera camera, double px, double py) {
        Ray ray = new Ray();
        camera.generateRay(viewPlane, px, py, 0.3, -0.2, ray);
        return ray;
    }

    private static void assertDirection(Vector3D expected, Ray ray, String where) {
        String message = where + ": the ray's direction must be " + expected + " (to 1e-12), got (" + ray.dx + ", " + ray.dy + ", "
                         + ray.dz + ")";
        assertEquals(expected.x(), ray.dx, 1e-12, message);
        assertEquals(expected.y(), ray.dy, 1e-12, message);
        assertEquals(expected.z(), ray.dz, 1e-12, message);
    }

    @Test
    void theCentreOfTheImageLooksAtTheLookAtPoint() {
        Ray ray = ray(camera(120, 60), WIDTH / 2.0, HEIGHT / 2.0);
        String origin = "Spherical(eye " + EYE + ", ...): every ray starts at the eye, got (" + ray.ox + ", " + ray.oy + ", " + ray.oz + ")";
        assertEquals(EYE.x(), ray.ox, 0, origin);
        assertEquals(EYE.y(), ray.oy, 0, origin);
        assertEquals(EYE.z(), ray.oz, 0, origin);
        assertDirection(w.negate(), ray, "Spherical(120, 60 degrees), the image's centre (200, 100) looks at the look-at point");
    }

    @Test
    void theEdgesAreHalfTheFieldsOfViewAway() {
        Camera camera = camera(120, 60);
        Ray left = ray(camera, 0, HEIGHT / 2.0);
        Vector3D d = new Vector3D(left.dx, left.dy, left.dz);
        String leftEdge = "Spherical(120, 60 degrees), pixel position (0, 100): the left edge is h/2 = 60 degrees to the left, "
                          + "so its direction d has d.u = -sin(60), -d.w = cos(60); got d = " + d;
        assertEquals(-Math.sin(Math.toRadians(60)), d.dot(u), 1e-12, leftEdge);
        assertEquals(Math.cos(Math.toRadians(60)), -d.dot(w), 1e-12, leftEdge);
        Ray top = ray(camera, WIDTH / 2.0, 0);
        Vector3D t = new Vector3D(top.dx, top.dy, top.dz);
        assertEquals(Math.sin(Math.toRadians(30)), t.dot(v), 1e-12,
                     "Spherical(120, 60 degrees), pixel position (200, 0): the top edge is v/2 = 30 degrees up, so d.v = sin(30); got d = " + t);
    }

    @Test
    void aFullPanoramaSeesAllAround() {
        Camera camera = camera(360, 180);
        assertDirection(v, ray(camera, WIDTH / 2.0, 0), "Spherical(360, 180), pixel position (200, 0): the top row looks straight up, +v");
        assertDirection(v.negate(), ray(camera, WIDTH / 2.0, HEIGHT), "Spherical(360, 180), (200, 200): the bottom row looks straight down, -v");
        assertDirection(w, ray(camera, 0, HEIGHT / 2.0), "Spherical(360, 180), (0, 100): the left edge looks backwards, +w");
        assertDirection(w, ray(camera, WIDTH, HEIGHT / 2.0), "Spherical(360, 180), (400, 100): the right edge looks backwards too, +w");
        assertDirection(u, ray(camera, 3 * WIDTH / 4.0, HEIGHT / 2.0), "Spherical(360, 180), (300, 100): three quarters across looks right, +u");
    }

    @Test
    void everyRayFollowsTheClosedForm() {
        Camera camera = camera(200, 100);
        SplittableRandom random = new SplittableRandom(2);
        for (int i = 0; i < 1000; i++) {
            double px = WIDTH * random.nextDouble();
            double py = HEIGHT * random.nextDouble();
            double lambda = (2 * px / WIDTH - 1) * Math.toRadians(100);
            double psi = (1 - 2 * py / HEIGHT) * Math.toRadians(50);
            Vector3D expected = u.scale(Math.cos(psi) * Math.sin(lambda)).add(v.scale(Math.sin(psi)))
                .sub(w.scale(Math.cos(psi) * Math.cos(lambda)));
            assertDirection(expected, ray(camera, px, py), "Spherical(200, 100 degrees), random pixel position (" + px + ", " + py
                                                           + "): cos(psi) sin(lambda) u + sin(psi) v - cos(psi) cos(lambda) w");
        }
    }

    @Test
    void itHasNoLens() {
        assertFalse(camera(90, 60).needsLensSamples(), "needsLensSamples() must be false: a pinhole-like camera has no lens");
    }

    @Test
    void fieldsOfViewOutOfRangeAreRefused() {
        String range = ": fields of view must be positive, at most 360 across and 180 up (IllegalArgumentException)";
        assertThrows(IllegalArgumentException.class, () -> camera(0, 60), "Spherical(..., 0, 60)" + range);
        assertThrows(IllegalArgumentException.class, () -> camera(361, 60), "Spherical(..., 361, 60)" + range);
        assertThrows(IllegalArgumentException.class, () -> camera(90, 181), "Spherical(..., 90, 181)" + range);
        assertThrows(IllegalArgumentException.class, () -> camera(90, Double.NaN), "Spherical(..., 90, NaN)" + range);
    }
}

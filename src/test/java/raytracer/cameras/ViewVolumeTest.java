package raytracer.cameras;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.Camera;
import raytracer.core.ViewPlane;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/**
 * Every point of every primary ray lies in the camera's view volume and every ray starts in its
 * box of origins: rays through the image's corners and edges and random pixels, from random lens
 * points, for random cameras at scales 1e-3 to 1e4, followed to distances 0 to 1e6.
 */
class ViewVolumeTest {
    private static final ViewPlane VP = new ViewPlane(64, 36, 1, (n, rng, xs, ys) -> { }, 0, 1);

    @Test
    void primaryRaysStayInTheVolume() {
        SplittableRandom random = new SplittableRandom(14);
        for (int c = 0; c < 60; c++) {
            double scale = Math.pow(10, random.nextDouble(-3, 4));
            Camera camera = randomCamera(random, c, scale);
            List<HalfSpace> volume = camera.viewVolume(VP);
            assertEquals(5, volume.size());
            BBox origins = camera.rayOrigins(VP);
            Ray ray = new Ray();
            for (int k = 0; k < 200; k++) {
                double px = k < 4 ? (k % 2) * VP.hres() : random.nextDouble() * VP.hres();
                double py = k < 4 ? (k / 2) * VP.vres() : random.nextDouble() * VP.vres();
                generate(camera, px, py, k, random, ray);
                assertTrue(origins.contains(ray.ox, ray.oy, ray.oz), () -> "origin outside " + origins);
                assertInside(camera, volume, ray, scale);
            }
        }
    }

    /**
     * The renderer's tiles: every ray through a window of the image stays in that window's
     * volume, and the volume is the window's, not the image's: a ray through the middle of
     * another window, a pixel or more away, leaves it.
     */
    @Test
    void raysThroughAWindowStayInItsVolume() {
        SplittableRandom random = new SplittableRandom(15);
        Ray ray = new Ray();
        int outsideFound = 0;
        for (int c = 0; c < 60; c++) {
            double scale = Math.pow(10, random.nextDouble(-3, 4));
            Camera camera = randomCamera(random, c, scale);
            double x0 = random.nextInt(VP.hres() - 4);
            double y0 = random.nextInt(VP.vres() - 4);
            double x1 = x0 + 1 + random.nextInt((int) (VP.hres() - x0) - 1);
            double y1 = y0 + 1 + random.nextInt((int) (VP.vres() - y0) - 1);
            List<HalfSpace> volume = camera.viewVolume(VP, x0, y0, x1, y1);
            assertEquals(5, volume.size());
            for (int k = 0; k < 200; k++) {
                double px = k < 4 ? (k % 2 == 0 ? x0 : x1) : x0 + random.nextDouble() * (x1 - x0);
                double py = k < 4 ? (k / 2 == 0 ? y0 : y1) : y0 + random.nextDouble() * (y1 - y0);
                generate(camera, px, py, k, random, ray);
                assertInside(camera, volume, ray, scale);
            }
            // a ray through the middle of the wider band of pixels beside the window, at least a pixel
            // from it: outside the volume of a pinhole or a parallel projection (a lens widens the
            // volume by its spread, which may exceed a pixel's slope)
            double px = x0 >= VP.hres() - x1 ? x0 / 2 : (x1 + VP.hres()) / 2;
            double py = (y0 + y1) / 2;
            if (camera instanceof ThinLens || px > x0 - 1 && px < x1 + 1) {
                continue;
            }
            camera.generateRay(VP, px, py, 0, 0, ray);
            double t = scale;
            double x = ray.ox + t * ray.dx;
            double y = ray.oy + t * ray.dy;
            double z = ray.oz + t * ray.dz;
            assertTrue(volume.stream().anyMatch(h -> !h.contains(x, y, z)),
                       () -> camera.getClass().getSimpleName() + ": the ray through pixel " + px + " stays in the volume of window "
                             + x0 + ".." + x1);
            outsideFound++;
        }
        assertTrue(outsideFound > 20, "too few windows had room beside them: " + outsideFound);
    }

    private static Camera randomCamera(SplittableRandom random, int c, double scale) {
        Point3D eye = new Point3D(random.nextDouble(-1, 1) * scale, random.nextDouble(-1, 1) * scale, random.nextDouble(-1, 1) * scale);
        Point3D at = new Point3D(eye.x() + random.nextDouble(-1, 1), eye.y() + random.nextDouble(-1, 1), eye.z() + 1);
        double fov = random.nextDouble(5, 150);
        return switch (c % 3) {
            case 0 -> new Pinhole(eye, at, Vector3D.UP, fov);
            case 1 -> new ThinLens(eye, at, Vector3D.UP, fov, random.nextDouble(0.01, 1) * scale, random.nextDouble(0.1, 10) * scale);
            default -> new Orthographic(eye, at, Vector3D.UP, random.nextDouble(0.1, 10) * scale);
        };
    }

    /** The ray through (px, py), from the lens's rim for the first eight rays, else from a random lens point. */
    private static void generate(Camera camera, double px, double py, int k, SplittableRandom random, Ray ray) {
        double angle = random.nextDouble(2 * Math.PI);
        double r = k < 8 ? 1 : Math.sqrt(random.nextDouble());
        camera.generateRay(VP, px, py, r * Math.cos(angle), r * Math.sin(angle), ray);
    }

    private static void assertInside(Camera camera, List<HalfSpace> volume, Ray ray, double scale) {
        for (double t : new double[] {0, 1e-3 * scale, scale, 1e3 * scale, 1e6 * scale}) {
            double x = ray.ox + t * ray.dx;
            double y = ray.oy + t * ray.dy;
            double z = ray.oz + t * ray.dz;
            for (HalfSpace h : volume) {
                double excess = h.nx() * x + h.ny() * y + h.nz() * z - h.d();
                double size = (Math.abs(h.nx()) + Math.abs(h.ny()) + Math.abs(h.nz()))
                              * Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z))) + Math.abs(h.d());
                // within rounding (1e-12 of the numbers' size), far inside the analysis's margin
                if (!(excess <= 1e-12 * size)) {
                    throw new AssertionError(camera.getClass().getSimpleName() + " ray at t = " + t + " leaves " + h
                                             + " by " + excess + " of " + size);
                }
            }
        }
    }
}

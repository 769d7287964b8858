package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.materials.Matte;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.shapes.Sphere;
import raytracer.tracers.RayCast;

/**
 * A Lambertian sphere under one point light, rendered with one sample at each pixel centre, against
 * the closed form L = kd cd / pi * I cos(theta) / r^2 computed here independently of the renderer.
 */
class AnalyticSphereTest {
    private static final int W = 64;
    private static final int H = 48;
    private static final double FOV = 40;
    private static final Point3D EYE = new Point3D(0, 0, 6);
    private static final Point3D LIGHT = new Point3D(3, 4, 5);
    private static final double INTENSITY = 30;
    private static final double KD = 0.8;
    private static final RGBColor CD = new RGBColor(0.9, 0.6, 0.3);

    @Test
    void everyPixelMatchesTheAnalyticRadiance() {
        ViewPlane vp = new ViewPlane(W, H, 1, CenterSampler.INSTANCE, 0, 1);
        World world = new World(vp, new Pinhole(EYE, Point3D.ORIGIN, Vector3D.UP, FOV), new Ambient(0, RGBColor.WHITE));
        Sphere sphere = new Sphere(Point3D.ORIGIN, 1.5);
        sphere.setMaterial(new Matte(0, KD, CD));
        world.addObject(sphere);
        world.addLight(new PointLight(INTENSITY, RGBColor.WHITE, LIGHT));
        world.setTracer(RayCast::new);
        world.prepare();
        Film film = new Film(W, H);
        Renders.render(world, 2, 1, film);

        int lit = 0;
        double worst = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double expected = analyticRadiance(x + 0.5, y + 0.5);
                double actual = film.get(x, y, 0) / CD.r();
                if (expected > 1e-3) {
                    lit++;
                    worst = Math.max(worst, Math.abs(actual - expected) / expected);
                } else {
                    assertEquals(expected, actual, 1e-7, "pixel " + x + "," + y);
                }
            }
        }
        assertTrue(lit > 500, "the sphere should cover many lit pixels, got " + lit);
        assertTrue(worst < 1e-6, "worst relative error " + worst);
    }

    /** Radiance of the red channel divided by cd.r, from first principles. */
    private static double analyticRadiance(double px, double py) {
        // pinhole ray: image plane at distance 1 with half-height tan(fov/2); the camera looks down -z
        double half = Math.tan(Math.toRadians(FOV) / 2);
        double dx = (2 * px / W - 1) * half * W / H;
        double dy = (1 - 2 * py / H) * half;
        double dz = -1;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= len;
        dy /= len;
        dz /= len;
        // |e + t d|^2 = r^2 with the textbook quadratic formula
        double ex = EYE.x();
        double ey = EYE.y();
        double ez = EYE.z();
        double b = 2 * (ex * dx + ey * dy + ez * dz);
        double c = ex * ex + ey * ey + ez * ez - 1.5 * 1.5;
        double disc = b * b - 4 * c;
        if (disc < 0) {
            return 0;
        }
        double t = (-b - Math.sqrt(disc)) / 2;
        double hx = ex + t * dx;
        double hy = ey + t * dy;
        double hz = ez + t * dz;
        double lx = LIGHT.x() - hx;
        double ly = LIGHT.y() - hy;
        double lz = LIGHT.z() - hz;
        double r2 = lx * lx + ly * ly + lz * lz;
        double cos = (hx * lx + hy * ly + hz * lz) / (1.5 * Math.sqrt(r2));
        // a convex sphere shadows itself exactly where cos <= 0
        return cos <= 0 ? 0 : KD / Math.PI * INTENSITY * cos / r2;
    }
}

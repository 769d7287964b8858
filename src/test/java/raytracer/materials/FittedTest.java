package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.brdf.BlinnPhong;
import raytracer.cameras.Orthographic;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.Directional;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.shapes.Plane;
import raytracer.tracers.RayCast;

/** The report's quirks, measured on a plane under a sun: diffuse differs by pi, the lobe by cos(theta_i). */
class FittedTest {

    private static double radiance(boolean seedCompatible, double rhoS) {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> {
            xs[0] = 0.5;
            ys[0] = 0.5;
        }, 0, 1), new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        Plane plane = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        plane.setMaterial(new Fitted(RGBColor.gray(0.4), new BlinnPhong(RGBColor.gray(rhoS), 10), 0, seedCompatible));
        world.addObject(plane);
        // sun at 60 degrees from the normal: cos(theta_i) = 0.5
        world.addLight(new Directional(2, RGBColor.WHITE, new Vector3D(Math.sqrt(3), 1, 0)));
        world.setTracer(RayCast::new);
        world.prepare();
        Film film = new Film(1, 1);
        Renders.render(world, 1, 1, film);
        return film.get(0, 0, 0);
    }

    @Test
    void physicalAndSeedCompatibleShadingDifferAsDocumented() {
        double cos = 0.5;
        double e = 2;
        // diffuse only: rho_d / pi * E cos, and without the 1/pi
        assertEquals(0.4 / Math.PI * e * cos, radiance(false, 0), 1e-6);
        assertEquals(0.4 * e * cos, radiance(true, 0), 1e-6);
        // the lobe alone: (n+2)/(2 pi) cos^n(theta_h) rho_s, times cos(theta_i) or not
        double cosH = Math.cos(Math.toRadians(30));
        double lobe = 0.2 * 12 / (2 * Math.PI) * Math.pow(cosH, 10);
        assertEquals(lobe * e * cos, radiance(false, 0.2) - radiance(false, 0), 1e-6);
        assertEquals(lobe * e, radiance(true, 0.2) - radiance(true, 0), 1e-6);
    }
}

package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cameras.Pinhole;
import raytracer.core.GeometricObject;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.materials.Matte;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;
import raytracer.tracers.RayCast;

/**
 * A sphere of radius R resting on y = 0 is, near the camera, the plane y = 0 (its surface sags by
 * x^2 / 2R, below 1e-4 units here): the image must be the plane's, lit, with the shadow of a ball
 * standing on it. Radii of 1e16 and more rendered ambient only: the ray's origin relative to the
 * centre (1 + R) is not a double, and the near root was lost.
 */
class HugeSphereTest {
    private static final int W = 64;
    private static final int H = 48;

    @ParameterizedTest
    @ValueSource(doubles = {1e6, 1e10, 1e14, 1e16, 1e18, 1e20, 1e25})
    void aHugeSphereRendersAsThePlaneItApproximates(double radius) {
        Film plane = render(new Plane(Point3D.ORIGIN, new Normal(0, 1, 0)));
        Film sphere = render(new Sphere(new Point3D(0, -radius, 0), radius));
        int differing = 0;
        double lit = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                float a = plane.get(x, y, 1);
                float b = sphere.get(x, y, 1);
                assertTrue(Float.isFinite(b));
                differing += Math.abs(a - b) > 1e-3 * Math.max(1, a) ? 1 : 0;
                lit += b;
            }
        }
        // silhouette pixels of the ball may flip under rounding; acne or a lost floor would be hundreds
        assertTrue(differing <= 3, "radius " + radius + ": " + differing + " pixels differ from the plane's image");
        assertTrue(lit / (W * H) > 0.05, "the floor is lit (ambient alone gives 0.016): mean " + lit / (W * H));
    }

    private static Film render(GeometricObject floor) {
        ViewPlane vp = new ViewPlane(W, H, 1, CenterSampler.INSTANCE, 3, 1);
        World world = new World(vp, new Pinhole(new Point3D(0, 1, 6), new Point3D(0, 0.3, 0), Vector3D.UP, 50),
                                new Ambient(0.1, RGBColor.WHITE));
        Matte matte = new Matte(0.2, 0.8, new RGBColor(0.8, 0.8, 0.8));
        floor.setMaterial(matte);
        world.addObject(floor);
        // a ball standing on the floor, between it and the light: its shadow needs shadow rays
        // starting close to the floor, not a whole error bound of 1e5 units above it
        Sphere ball = new Sphere(new Point3D(0, 0.5, 0), 0.5);
        ball.setMaterial(matte);
        world.addObject(ball);
        world.addLight(new PointLight(40, RGBColor.WHITE, new Point3D(-2, 4, -1)));
        world.setTracer(RayCast::new);
        world.prepare();
        Film film = new Film(W, H);
        assertEquals(0, Renders.render(world, 1, 1, film).nonFiniteSamples());
        return film;
    }
}

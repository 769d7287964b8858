package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.Light;
import raytracer.core.Sampler;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.AreaLight;
import raytracer.lights.Directional;
import raytracer.lights.PointLight;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.TriangleMesh;
import raytracer.tracers.AreaLighting;
import raytracer.tracers.Whitted;

/**
 * Direct light through a shading normal that differs from the surface's: a floor triangle at y = 0
 * whose vertex normals all lean 60 degrees towards +x, seen from above at its point (0, 0, 0). A
 * light below the floor but in front of the leaning normal must add nothing: the surface hides it,
 * whatever the normal used for shading says. A light above the floor lights it through the leaning
 * normal, Lambert's f L cos(theta_i) with cos taken from that normal.
 */
class DirectLightingTest {
    private static final Sampler CENTRE = (n, rng, xs, ys) -> {
        xs[0] = 0.5;
        ys[0] = 0.5;
    };
    private static final double LEAN = Math.toRadians(60);
    /** The shading normal, (sin 60, cos 60, 0), as the mesh stores it (floats). */
    private static final double[] SHADING = {(float) Math.sin(LEAN), (float) Math.cos(LEAN), 0};
    private static final List<Function<World, Tracer>> TRACERS = List.of(Whitted::new, AreaLighting::new);

    /** The one pixel, looking straight down at the origin, lit by {@code light} alone. */
    private static double render(Light light, Function<World, Tracer> tracer) {
        World world = new World(new ViewPlane(1, 1, 1, CENTRE, 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 0.1), new Ambient(0, RGBColor.WHITE));
        // one triangle around the origin, wound so that its face normal is +y
        double[] p = {-10, 0, -10, -10, 0, 10, 10, 0, 0};
        float sx = (float) SHADING[0];
        float sy = (float) SHADING[1];
        float[] n = {sx, sy, 0, sx, sy, 0, sx, sy, 0};
        TriangleMesh floor = new TriangleMesh(new Mesh(p, n, null, new int[] {0, 1, 2}, new int[] {0}),
                                              List.of(new Matte(0, 1, RGBColor.WHITE)));
        world.addObject(floor);
        world.addLight(light);
        world.setTracer(tracer);
        world.prepare();
        Film film = new Film(1, 1);
        Renders.render(world, 1, 1, film);
        assertEquals(film.get(0, 0, 0), film.get(0, 0, 2), 0, "a white light on a white surface is grey");
        return film.get(0, 0, 0);
    }

    @Test
    void aLightBelowTheSurfaceAddsNothingThoughTheShadingNormalFacesIt() {
        // each is in front of the leaning normal (n . wi > 0) and below the floor (y < 0)
        for (Function<World, Tracer> tracer : TRACERS) {
            assertEquals(0, render(new PointLight(50, RGBColor.WHITE, new Point3D(3, -0.5, 0)), tracer), 0, "point light");
            assertEquals(0, render(new PointLight(50, RGBColor.WHITE, new Point3D(0.5, -2, 0.3)), tracer), 0, "point light");
            assertEquals(0, render(new Directional(3, RGBColor.WHITE, new Vector3D(1, -0.2, 0)), tracer), 0, "directional light");
            Light unshadowed = new PointLight(50, RGBColor.WHITE, new Point3D(3, -0.5, 0));
            unshadowed.setCastsShadows(false);
            assertEquals(0, render(unshadowed, tracer), 0, "point light casting no shadows");
        }
    }

    /**
     * A parallelogram light facing -x at x = 3, area 3 (edges 2 along z and (0, 1.5, 0.3)), reaching
     * through the floor's plane: its part above the floor may light the point, so the light is not
     * passed over as a whole, and the one sample is taken at its centre (0.5, 0.5 of the edges, as
     * the one-point sampler puts it; its edges are not perpendicular, so it is sampled by area, not by
     * solid angle), at height {@code centreY}.
     */
    private static AreaLight straddling(double centreY) {
        return AreaLight.rectangle(new Point3D(3, centreY - 0.75, -1.15), new Vector3D(0, 0, 2), new Vector3D(0, 1.5, 0.3), 4,
                                   RGBColor.WHITE, 1);
    }

    @Test
    void anAreaLightSampleBelowTheSurfaceAddsNothing() {
        assertEquals(0, render(straddling(-0.25), AreaLighting::new), 0);
        // the sample above: kd / pi * Le * cos(theta_i) * cos(theta_light) / r^2 / pdf, pdf = 1 / area
        double r2 = 9 + 0.25 * 0.25;
        double cos = (SHADING[0] * 3 + SHADING[1] * 0.25) / Math.sqrt(r2);
        double cosLight = 3 / Math.sqrt(r2);
        assertEquals(4 * cos * cosLight / r2 * 3 / Math.PI, render(straddling(0.25), AreaLighting::new), 1e-6);
    }

    @Test
    void aLightAboveTheSurfaceLightsItThroughTheShadingNormal() {
        // the mirror images of the lights above: kd / pi * E, with E = I cos / r^2 or ls cos
        for (Function<World, Tracer> tracer : TRACERS) {
            double[] at = {3, 0.5, 0};
            double r2 = at[0] * at[0] + at[1] * at[1];
            double cos = (SHADING[0] * at[0] + SHADING[1] * at[1]) / Math.sqrt(r2);
            assertEquals(50 * cos / r2 / Math.PI, render(new PointLight(50, RGBColor.WHITE, new Point3D(3, 0.5, 0)), tracer), 1e-6);
            double cosDirectional = (SHADING[0] * 1 + SHADING[1] * 0.2) / Math.sqrt(1.04);
            assertEquals(3 * cosDirectional / Math.PI, render(new Directional(3, RGBColor.WHITE, new Vector3D(1, 0.2, 0)), tracer), 1e-6);
        }
    }
}

package raytracer.render;

import raytracer.cameras.Orthographic;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.Vector3D;
import raytracer.samplers.Regular;
import raytracer.shapes.Plane;
import raytracer.tracers.RayCast;

/**
 * A test-only scene whose material returns NaN or +Inf in two vertical stripes, so that the renderer's
 * path for non-finite samples runs with a count known in advance. An orthographic camera with a
 * window W x H units wide puts image column x at world x, and the regular 2 x 2 pattern samples each
 * pixel at offsets 0.25 and 0.75, so every sample's column is known: the stripe edges lie halfway
 * between samples, far from any rounding.
 */
public final class NonFiniteScene {
    public static final int W = 16;
    public static final int H = 8;
    /** Red is NaN for 4.5 <= x < 6.5: pixel 4 has 2 such samples of 4, pixel 5 all 4, pixel 6 two. */
    static final double NAN_FROM = 4.5;
    static final double NAN_TO = 6.5;
    /** Green is +Inf for 10.5 <= x < 11.5: two samples each of pixels 10 and 11. */
    static final double INF_FROM = 10.5;
    static final double INF_TO = 11.5;
    /** 8 NaN and 4 Inf samples a row. */
    public static final long NON_FINITE_SAMPLES = 12L * H;
    static final RGBColor COLOR = new RGBColor(0.2, 0.4, 0.6);

    private NonFiniteScene() {
    }

    public static World world() {
        ViewPlane vp = new ViewPlane(W, H, 4, new Regular(), 1, 1);
        World world = new World(vp, new Orthographic(new Point3D(W / 2.0, 0, 5), new Point3D(W / 2.0, 0, 0), Vector3D.UP, H),
                                new Ambient(0, RGBColor.WHITE));
        Plane wall = new Plane(Point3D.ORIGIN, new Normal(0, 0, 1));
        wall.setMaterial(new Stripes());
        world.addObject(wall);
        world.setTracer(RayCast::new);
        world.prepare();
        return world;
    }

    /** The faulty material: a constant colour but for a NaN stripe and an Inf stripe. */
    static final class Stripes extends Material {
        @Override
        public void shade(ShadeRec sr, MutableRgb out) {
            out.set(COLOR);
            double x = sr.hitPoint.x;
            if (x >= NAN_FROM && x < NAN_TO) {
                out.r = Double.NaN;
            } else if (x >= INF_FROM && x < INF_TO) {
                out.g = Double.POSITIVE_INFINITY;
            }
        }

        @Override
        public void areaLightShade(ShadeRec sr, MutableRgb out) {
            shade(sr, out); // the scene has no area light; the tracer may call either
        }
    }
}

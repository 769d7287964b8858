package raytracer.tracers;

import raytracer.core.Background;
import raytracer.core.ShadeRec;
import raytracer.core.Tracer;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.Ray;
import raytracer.math.Rgb;

/**
 * Whitted's tracer (Suffern, section 24.4): materials may trace secondary rays, and rays deeper than
 * the view plane's max depth return black.
 */
public final class Whitted implements Tracer {
    private final World world;

    public Whitted(World world) {
        this.world = world;
    }

    @Override
    public void traceRay(Ray ray, int depth, WorkerScratch scratch, Rgb out) {
        if (depth > world.viewPlane().maxDepth()) {
            out.setBlack();
            return;
        }
        shadeClosest(world, ray, depth, scratch, out);
    }

    /**
     * The tracers' common step: the closest hit's material shades it, and a ray that escapes sees
     * the background, or the reflection map of the object it left (a per-object environment).
     */
    static void shadeClosest(World world, Ray ray, int depth, WorkerScratch scratch, Rgb out) {
        ShadeRec sr = scratch.shadeRec(depth);
        sr.depth = depth;
        if (world.hit(ray, sr)) {
            sr.material.shade(sr, out);
        } else {
            Background environment = scratch.environment(depth);
            (environment != null ? environment : world.background()).radiance(ray, out);
        }
    }
}

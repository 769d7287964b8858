package raytracer.tracers;

import raytracer.core.ShadeRec;
import raytracer.core.Tracer;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/**
 * Whitted's tracer (Suffern, section 24.4): the closest hit's material shades it with
 * {@code shade}, tracing secondary rays back through this tracer; rays deeper than the view
 * plane's max depth return black. Lights are taken from one direction each, so a scene with area
 * lights needs {@link AreaLighting}.
 */
public final class Whitted implements Tracer {
    private final World world;

    public Whitted(World world) {
        this.world = world;
    }

    @Override
    public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
        if (depth > world.viewPlane().maxDepth()) {
            out.setBlack();
            return;
        }
        ShadeRec sr = ClosestHit.find(world, ray, depth, scratch, out);
        if (sr != null) {
            sr.material.shade(sr, out);
        }
    }
}

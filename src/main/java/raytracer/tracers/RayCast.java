package raytracer.tracers;

import raytracer.core.ShadeRec;
import raytracer.core.Tracer;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/**
 * The ray-cast tracer (Suffern, section 14.5): only primary rays are shaded, with {@code shade}.
 * A secondary ray asked for by a mirror returns black, so the image shows direct light alone.
 */
public final class RayCast implements Tracer {
    private final World world;

    public RayCast(World world) {
        this.world = world;
    }

    @Override
    public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
        if (depth > 0) {
            out.setBlack();
            return;
        }
        ShadeRec sr = ClosestHit.find(world, ray, depth, scratch, out);
        if (sr != null) {
            sr.material.shade(sr, out);
        }
    }

    /** Secondary rays return black before any object is tested. */
    @Override
    public boolean tracesSecondaryRays() {
        return false;
    }
}

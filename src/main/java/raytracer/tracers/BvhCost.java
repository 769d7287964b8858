package raytracer.tracers;

import raytracer.core.ShadeRec;
import raytracer.core.Tracer;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/**
 * The report's debug view (figure 9): instead of radiance, each primary ray returns the number of
 * bounding-volume tests its closest-hit search made, in all three channels. The caller maps the
 * counts to false colour.
 */
public final class BvhCost implements Tracer {
    private final World world;

    public BvhCost(World world) {
        this.world = world;
    }

    @Override
    public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
        ShadeRec sr = scratch.shadeRec(depth);
        sr.depth = depth;
        long before = sr.boxTests;
        world.hit(ray, sr);
        double tests = sr.boxTests - before;
        out.set(tests, tests, tests);
    }

    /** Only camera rays are traced, and nothing is shaded. */
    @Override
    public boolean tracesSecondaryRays() {
        return false;
    }
}

package raytracer.tracers;

import raytracer.core.ShadeRec;
import raytracer.core.Tracer;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/**
 * The area-lighting tracer (Suffern, chapter 18): Whitted's recursion, but the closest hit's
 * material shades it with {@code areaLightShade}, which samples each light and weighs the samples
 * by G / pdf, so that area lights give soft light and shadows. Secondary rays come back through
 * this tracer and are shaded the same way. For lights without extent (G = pdf = 1, one sample) it
 * gives Whitted's image, bit for bit.
 */
public final class AreaLighting implements Tracer {
    private final World world;

    public AreaLighting(World world) {
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
            sr.material.areaLightShade(sr, out);
        }
    }
}

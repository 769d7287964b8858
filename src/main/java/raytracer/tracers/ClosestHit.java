package raytracer.tracers;

import raytracer.core.Background;
import raytracer.core.ShadeRec;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/** The tracers' common step: the closest hit to shade, or the environment a ray escapes to. */
final class ClosestHit {
    private ClosestHit() {
    }

    /**
     * Returns the completed closest hit of {@code ray}, traced at {@code depth}, for its material
     * to shade (the rays it traces get a sample path of their own until its material names them);
     * or null after writing into {@code out} what the escaping ray sees: the background,
     * or the reflection map of the object it left (a per-object environment).
     */
    static ShadeRec find(World world, Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
        ShadeRec sr = scratch.shadeRec(depth);
        sr.depth = depth;
        if (world.hit(ray, sr)) {
            scratch.samples.inherit(depth);
            return sr;
        }
        Background environment = scratch.environment(depth);
        (environment != null ? environment : world.background()).radiance(ray, out);
        return null;
    }
}

package raytracer.study;

import raytracer.core.ShadeRec;
import raytracer.core.Tracer;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableRgb;
import raytracer.math.RGBColor;
import raytracer.math.Ray;

/**
 * Whitted's tracer (Suffern, section 24.4) in the textbook's Java: each trace returns a new colour.
 * The closest hit is found by the renderer's own search of {@code world} (its BVHs, its two-phase
 * hits) in the worker's hit record, which the study asks to be a new one for every ray; from the
 * completed hit on, everything is a new value. Shading only depth 0, it is the ray-cast tracer.
 */
final class ImmutableWhitted implements Tracer {
    private final World world;
    /** The view plane's max depth: materials trace no deeper. */
    private final int maxDepth;
    /** The deepest rays that are shaded: maxDepth for Whitted, 0 for ray casting (Suffern, section 14.5). */
    private final int shadedDepth;
    private final ImmutableLight[] lights;
    private final RGBColor ambient;
    private final Translation.Materials materials;

    ImmutableWhitted(World world, int maxDepth, int shadedDepth, ImmutableLight[] lights, RGBColor ambient, Translation.Materials materials) {
        this.world = world;
        this.maxDepth = maxDepth;
        this.shadedDepth = shadedDepth;
        this.lights = lights;
        this.ambient = ambient;
        this.materials = materials;
    }

    /** The renderer's entry: the pixel loop keeps its own accumulator, so the colour is copied into it. */
    @Override
    public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
        out.set(trace(ray, depth, scratch));
    }

    RGBColor trace(Ray ray, int depth, WorkerScratch scratch) {
        if (depth > shadedDepth) {
            return RGBColor.BLACK;
        }
        ShadeRec sr = scratch.shadeRec(depth);
        sr.depth = depth;
        if (!world.hit(ray, sr)) {
            MutableRgb sky = new MutableRgb();
            world.background().radiance(ray, sky);
            return sky.toColor();
        }
        return materials.of(sr.material).shade(Hit.of(sr, ray), this);
    }

    /** True when a shadow-casting object lies on {@code ray} before {@code distance}. */
    boolean inShadow(Ray ray, double distance, Hit hit) {
        return world.shadowHit(ray, distance, hit.record());
    }

    int maxDepth() {
        return maxDepth;
    }

    ImmutableLight[] lights() {
        return lights;
    }

    RGBColor ambient() {
        return ambient;
    }
}

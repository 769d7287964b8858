package raytracer.study;

import java.util.Locale;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadeRecSupply;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.render.Renderer;
import raytracer.render.Workers;

/**
 * The three ways of the allocation study, which trace the same rays through the same arithmetic
 * and differ only in what they allocate per ray: {@link #REUSE}, the renderer's; {@link #FRESH}, a
 * new hit record (with its nine vectors and eight scratch rays) for every ray; {@link #IMMUTABLE},
 * new hit records and, from the completed hit on, a new immutable vector or colour for every step
 * of shading and light sampling, and a new ray for every shadow and mirror ray.
 */
public enum AllocationMode {
    REUSE(ShadeRecSupply.REUSE),
    FRESH(ShadeRecSupply.FRESH),
    IMMUTABLE(ShadeRecSupply.FRESH);

    private final ShadeRecSupply shadeRecs;

    AllocationMode(ShadeRecSupply shadeRecs) {
        this.shadeRecs = shadeRecs;
    }

    /**
     * Readies a prepared {@code world} for this mode, once: the immutable mode makes the textbook
     * tracer the world's (and refuses, with a message, what it cannot render); the others leave it.
     */
    public void install(World world, RayTreeSettings rayTree) {
        if (this == IMMUTABLE) {
            ImmutableWhitted whitted = Translation.whitted(world, rayTree);
            world.setTracer(w -> whitted);
        }
    }

    /** A renderer whose workers take their hit records as this mode does. */
    public Renderer renderer(World world, RayTreeSettings rayTree, Workers workers, long seed) {
        return new Renderer(world, rayTree, workers, seed, shadeRecs);
    }

    /** A worker's scratch for this mode, for work driven one pixel at a time. */
    public WorkerScratch scratch(World world, RayTreeSettings rayTree) {
        return new WorkerScratch(world, rayTree, shadeRecs);
    }

    /** The lower-case name, as the benchmark's parameter spells it. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    public static AllocationMode parse(String key) {
        for (AllocationMode mode : values()) {
            if (mode.key().equals(key)) {
                return mode;
            }
        }
        throw new IllegalArgumentException("unknown allocation mode '" + key + "'; allowed: reuse, fresh, immutable");
    }
}

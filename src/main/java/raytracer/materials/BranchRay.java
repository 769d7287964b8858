package raytracer.materials;

import raytracer.core.Background;
import raytracer.core.ShadeRec;
import raytracer.core.WorkerScratch;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Ray;

/**
 * One branch of a hit's ray tree (Suffern, chapters 24 to 28): a reflected, refracted or glossy
 * ray, spawned off the surface, named as its slot of the pixel's sample path, and traced one level
 * deeper with the environment it sees when it escapes.
 */
final class BranchRay {
    private BranchRay() {
    }

    /** Traces the hit's one ray {@code branch} (a {@link raytracer.core.PixelSamples} slot) in {@code direction}; its radiance goes to {@code out}. */
    static void trace(ShadeRec sr, MutableVec3 direction, int branch, WorkerScratch scratch, MutableRgb out, Background environment) {
        trace(sr, direction, branch, 0, 1, scratch, out, environment);
    }

    /** As above, for ray {@code i} of the {@code n} the hit traces in slot {@code branch}. */
    static void trace(ShadeRec sr, MutableVec3 direction, int branch, int i, int n, WorkerScratch scratch, MutableRgb out,
                      Background environment) {
        int depth = sr.depth + 1;
        Ray ray = sr.spawnRay(direction.x, direction.y, direction.z, scratch.ray(depth));
        scratch.samples.branch(sr.depth, branch, i, n);
        scratch.secondaryRays++;
        scratch.setEnvironment(depth, environment);
        sr.world.tracer().traceRay(ray, depth, scratch, out);
    }
}

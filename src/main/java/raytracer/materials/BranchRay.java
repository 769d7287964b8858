package raytracer.materials;

import raytracer.core.Background;
import raytracer.core.ShadeRec;
import raytracer.core.WorkerScratch;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Ray;

/**
 * One branch of a glass hit's ray tree (Suffern, chapter 27): the reflected or the refracted
 * (transmitted) ray, spawned off the surface, named as its slot of the pixel's sample path, and
 * traced one level deeper with the environment it sees when it escapes.
 */
final class BranchRay {
    private BranchRay() {
    }

    /** Traces the hit's ray {@code branch} (a {@link raytracer.core.PixelSamples} slot) in {@code direction}; its radiance goes to {@code out}. */
    static void trace(ShadeRec sr, MutableVec3 direction, int branch, WorkerScratch scratch, MutableRgb out, Background environment) {
        int depth = sr.depth + 1;
        Ray ray = sr.spawnRay(direction.x, direction.y, direction.z, scratch.ray(depth));
        scratch.samples.branch(sr.depth, branch, 0, 1);
        scratch.secondaryRays++;
        scratch.setEnvironment(depth, environment);
        sr.world.tracer().traceRay(ray, depth, scratch, out);
    }
}

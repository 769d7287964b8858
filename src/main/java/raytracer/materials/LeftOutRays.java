package raytracer.materials;

import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Skipped;

/**
 * A material's secondary rays that the scene analysis proved weigh 0 (a mirror whose kr cr is 0)
 * while nothing in the scene draws random numbers their subtrees would have drawn: not traced,
 * and counted where they would have been, within the max depth of the analysis (it may cut the
 * depth after) and, under a cutoff, only where a ray of weight 0 would have been kept.
 */
final class LeftOutRays {
    private final int maxDepth;

    LeftOutRays(int maxDepth) {
        this.maxDepth = maxDepth;
    }

    /** Counts the ray the hit {@code sr} would have traced. */
    void count(ShadeRec sr) {
        RayTreePolicy policy = sr.scratch.policy;
        if (sr.depth + 1 <= maxDepth && policy.showsReflection(sr.depth) && policy.recordBranchWeight(sr.depth, 0, 0, 0)) {
            sr.scratch.skipped[Skipped.SECONDARY_RAYS]++;
        }
    }

    /** The analysis's record of the decision, for --stats. */
    Skip skip(String rays, String material, String why) {
        return new Skip(Skipped.SECONDARY_RAYS, rays + " of weight 0 not traced",
                        "material '" + material + "': " + why + ", and no light or material of the scene draws random numbers");
    }
}

package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.MutableVec3;
import raytracer.math.Rounding;

/**
 * The hit record (Suffern, section 3.5), mutable and reused: one per recursion depth per worker.
 *
 * <p>Hits are two-phase, as in pbrt, Mitsuba and Sunflow. During the search, {@code hit} methods only
 * call {@link #recordHit} with t, the leaf object and what it needs to finish ({@link #primitive},
 * {@link #b1}, {@link #b2}); instances push themselves with {@link #pushTransform}. The winner is then
 * completed once by {@link #complete}: hit point, normals, error bound, u/v and material.
 */
public final class ShadeRec {
    /** Instances may nest this deep (an instance of an instance of ...). */
    public static final int MAX_NESTING = 8;

    // ---- search phase ----
    /** Distance of the closest hit so far; a hit method accepts only 0 < t < this. */
    public double t;
    /** The leaf object that holds the closest hit, or null. */
    public GeometricObject object;
    /** Which part of the leaf was hit (a triangle's index in a mesh). */
    public int primitive;
    /** Leaf data kept for completion (barycentric coordinates of a triangle hit). */
    public double b1;
    public double b2;

    private final LocalFrame[] transforms = new LocalFrame[MAX_NESTING];
    private int transformCount;
    private final Ray[] localRays = new Ray[MAX_NESTING];
    private int nesting;

    /** Bounding-volume tests made for this ray, for statistics and the BVH-cost view. */
    public long boxTests;

    // ---- completed for the winner ----
    /** World-space hit point (object space while a leaf's completeHit runs). */
    public final MutableVec3 hitPoint = new MutableVec3();
    /** The hit point in the leaf's own coordinates, for textures. */
    public final MutableVec3 localHitPoint = new MutableVec3();
    /** Unit shading normal, turned to face the incoming ray. */
    public final MutableVec3 normal = new MutableVec3();
    /** Unit geometric normal, on the same side as {@link #normal}. */
    public final MutableVec3 geometricNormal = new MutableVec3();
    /** Per-axis bound on the rounding error of {@link #hitPoint} (pbrt-v3, section 3.9). */
    public final MutableVec3 hitError = new MutableVec3();
    /** True when the ray arrived from the side the geometric normal pointed to before flipping. */
    public boolean frontFace;
    public double u;
    public double v;
    public Material material;

    // ---- context ----
    /** The ray being traced. */
    public Ray ray;
    public int depth;
    public final World world;
    public final WorkerScratch scratch;
    /** Shading scratch: unit direction to the viewer and to the light. */
    public final MutableVec3 wo = new MutableVec3();
    public final MutableVec3 wi = new MutableVec3();
    /** The point and unit normal of the last area-light sample. */
    public final MutableVec3 lightPoint = new MutableVec3();
    public final MutableVec3 lightNormal = new MutableVec3();

    public ShadeRec(World world, WorkerScratch scratch) {
        this.world = world;
        this.scratch = scratch;
        for (int i = 0; i < MAX_NESTING; i++) {
            localRays[i] = new Ray();
        }
    }

    /** Starts a closest-hit search for {@code ray} with nothing hit yet. */
    public void beginSearch(Ray ray, int depth, double tMax) {
        this.ray = ray;
        this.depth = depth;
        t = tMax;
        object = null;
        transformCount = 0;
        nesting = 0;
    }

    /** Called by a leaf that found a hit closer than {@link #t}. */
    public void recordHit(double t, GeometricObject leaf) {
        this.t = t;
        this.object = leaf;
        transformCount = 0;
    }

    /** Called by an instance whose content just recorded the closest hit. */
    public void pushTransform(LocalFrame frame) {
        transforms[transformCount++] = frame;
    }

    /** Borrows a ray for an instance to transform into; pair with {@link #releaseLocalRay}. */
    public Ray borrowLocalRay() {
        if (nesting == MAX_NESTING) {
            throw new IllegalStateException("instances nested deeper than " + MAX_NESTING);
        }
        return localRays[nesting++];
    }

    public void releaseLocalRay() {
        nesting--;
    }

    /** True when the closest hit was found inside an instance, in its object's local space. */
    public boolean isTransformed() {
        return transformCount > 0;
    }

    public boolean hitAnObject() {
        return object != null;
    }

    /**
     * Completes the closest hit: the leaf fills in its own coordinates, each enclosing instance
     * (innermost first) takes the result to its parent's space, then the normals are turned towards
     * the viewer.
     */
    public void complete(Ray worldRay) {
        Ray local = worldRay;
        for (int i = transformCount - 1; i >= 0; i--) {
            Ray next = localRays[i];
            transforms[i].toLocal(local, next);
            local = next;
        }
        material = object.getMaterial();
        object.completeHit(local, this);
        localHitPoint.set(hitPoint);
        for (int i = 0; i < transformCount; i++) {
            transforms[i].toWorld(this);
        }
        normal.normalize();
        geometricNormal.normalize();
        // A ray tangent to a surface touches it without crossing, and the shapes report no hit for
        // it (a double root, a ray in a flat shape's plane, an empty slab interval), so that a
        // closed solid is always entered before it is left. A hit that still arrives here with
        // n . d = 0 (rounding through an instance's matrices) is taken as seen from the front, the
        // side the ray has been on: spawnRay then continues it on that side, so it enters and leaves
        // at once, and no material takes the way from its origin as a path through its inside
        // (taken as a back face, glass applied Beer's law from the camera to its silhouette).
        frontFace = geometricNormal.dot(worldRay.dx, worldRay.dy, worldRay.dz) <= 0;
        if (!frontFace) {
            normal.negate();
            geometricNormal.negate();
        }
        if (normal.dot(geometricNormal) < 0) {
            // an interpolated normal may lean past the surface; keep it on the viewer's side
            normal.set(geometricNormal);
        }
    }

    /**
     * Starts {@code out} at the hit point, offset along the geometric normal by the hit point's
     * error bound to the side {@code (dx, dy, dz)} leaves on, and rounded one ulp further away
     * (pbrt-v3, section 3.9.5). The offset scales with the scene, so there is no epsilon to tune.
     */
    public Ray spawnRay(double dx, double dy, double dz, Ray out) {
        MutableVec3 n = geometricNormal;
        double d = Math.abs(n.x) * hitError.x + Math.abs(n.y) * hitError.y + Math.abs(n.z) * hitError.z;
        if (n.dot(dx, dy, dz) < 0) {
            d = -d;
        }
        double ox = nudge(hitPoint.x + d * n.x, d * n.x);
        double oy = nudge(hitPoint.y + d * n.y, d * n.y);
        double oz = nudge(hitPoint.z + d * n.z, d * n.z);
        return out.set(ox, oy, oz, dx, dy, dz);
    }

    /**
     * Starts {@code out} at the hit point offset towards the point q = (qx, qy, qz), as
     * {@link #spawnRay} does, and aims it at q: the direction is q - o, unnormalised, so that the
     * ray reaches q at t = 1, its extent measured from the offset origin, not from the hit point.
     * The subtraction's rounding is recorded as the ray's {@link Ray#directionError}, so that a
     * surface through q is seen to touch the ray's end rather than cross before it. q is where
     * the ray must stop: a light's point, itself offset off its surface by its error bound.
     */
    public Ray spawnRayTo(double qx, double qy, double qz, Ray out) {
        spawnRay(qx - hitPoint.x, qy - hitPoint.y, qz - hitPoint.z, out);
        double dx = qx - out.ox;
        double dy = qy - out.oy;
        double dz = qz - out.oz;
        double largest = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
        return out.set(out.ox, out.oy, out.oz, dx, dy, dz).setErrors(0, Rounding.gamma(1) * largest);
    }

    private static double nudge(double value, double offset) {
        if (offset > 0) {
            return Math.nextUp(value);
        }
        if (offset < 0) {
            return Math.nextDown(value);
        }
        return value;
    }

    /**
     * The density, over the light's area, with which its sampling picked {@link #lightPoint} (a
     * light that samples by solid angle gives pdf_omega cos(theta_light) / d^2), for {@link Light#pdf}.
     */
    public double lightPdf;
}

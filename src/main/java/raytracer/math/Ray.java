package raytracer.math;

/**
 * A ray {@code o + t d}. Mutable on purpose: each worker owns one ray per recursion depth and
 * overwrites it, so secondary rays cost no allocation. The direction need not be unit length
 * (an {@code Instance} keeps t unchanged by not renormalising). What tests derive from the ray
 * (1/d for slab tests, the watertight test's shear) is computed by whoever runs them, into
 * {@link SlabRay} and {@link ShearedRay}, so nothing here can go stale.
 */
public final class Ray {
    public double ox;
    public double oy;
    public double oz;
    public double dx;
    public double dy;
    public double dz;
    /**
     * How far the origin may lie from the exact one, on every axis: zero for a ray made where its
     * objects live, the transform's rounding for one an {@code Instance} took into its object's
     * space. Shadow tests widen their bounds on t by it (see {@link #directionError}).
     */
    public double originError;
    /**
     * How far each component of the direction may lie from the exact one: the rounding of q - o
     * for a shadow ray aimed at a point q ({@code ShadeRec.spawnRayTo}), plus an instance's. A
     * surface through q then meets the exact ray within (originError + t directionError) |n|_1 /
     * |n . d| of where it meets this one.
     */
    public double directionError;

    /** Sets the ray, taken as exact (no origin or direction error). */
    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.dx = dx;
        this.dy = dy;
        this.dz = dz;
        originError = 0;
        directionError = 0;
        return this;
    }

    /** Sets the bounds on the rounding of the origin and the direction (per axis); after {@link #set}. */
    public Ray setErrors(double originError, double directionError) {
        this.originError = originError;
        this.directionError = directionError;
        return this;
    }

    /** Direction component by axis index 0, 1, 2. */
    public double component(int axis) {
        return axis == 0 ? dx : axis == 1 ? dy : dz;
    }

    /** Origin component by axis index 0, 1, 2. */
    public double originComponent(int axis) {
        return axis == 0 ? ox : axis == 1 ? oy : oz;
    }

    public Ray set(Point3D o, Vector3D d) {
        return set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
    }

    public Ray set(Ray r) {
        return set(r.ox, r.oy, r.oz, r.dx, r.dy, r.dz).setErrors(r.originError, r.directionError);
    }

    public double atX(double t) {
        return ox + t * dx;
    }

    public double atY(double t) {
        return oy + t * dy;
    }

    public double atZ(double t) {
        return oz + t * dz;
    }

    @Override
    public String toString() {
        return "Ray[o=(" + ox + ", " + oy + ", " + oz + "), d=(" + dx + ", " + dy + ", " + dz + ")]";
    }
}

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

    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.dx = dx;
        this.dy = dy;
        this.dz = dz;
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
        return set(r.ox, r.oy, r.oz, r.dx, r.dy, r.dz);
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

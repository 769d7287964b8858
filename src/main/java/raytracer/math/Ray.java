package raytracer.math;

/**
 * A ray {@code o + t d}. Mutable on purpose: each worker owns one ray per recursion depth and
 * overwrites it, so secondary rays cost no allocation. The direction need not be unit length
 * (an {@code Instance} keeps t unchanged by not renormalising); {@code inv*} caches 1/d for slab tests.
 */
public final class Ray {
    public double ox;
    public double oy;
    public double oz;
    public double dx;
    public double dy;
    public double dz;
    public double invDx;
    public double invDy;
    public double invDz;
    /**
     * Constants of the watertight ray/triangle test (Woop, Benthin and Wald 2013, section 3): the
     * dominant axis kz of d, the two others kx, ky (swapped to keep winding), and the shear.
     */
    public int kx;
    public int ky;
    public int kz;
    public double shearX;
    public double shearY;
    public double shearZ;
    /** The origin's coordinates on the axes kx, ky, kz. */
    public double originKx;
    public double originKy;
    public double originKz;
    /**
     * For each axis, the offset (0 or 3) of the near slab plane in a box stored as
     * (x0, y0, z0, x1, y1, z1): the low plane when the ray runs towards +axis.
     */
    public int nearX;
    public int nearY;
    public int nearZ;

    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.dx = dx;
        this.dy = dy;
        this.dz = dz;
        invDx = 1.0 / dx;
        invDy = 1.0 / dy;
        invDz = 1.0 / dz;
        // by the sign of 1/d, not of d: a component -0.0 has 1/d = -infinity, so its near plane is the high one
        nearX = invDx < 0 ? 3 : 0;
        nearY = invDy < 0 ? 3 : 0;
        nearZ = invDz < 0 ? 3 : 0;
        prepareShear();
        return this;
    }

    private void prepareShear() {
        double ax = Math.abs(dx);
        double ay = Math.abs(dy);
        double az = Math.abs(dz);
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        double dkz = component(kz);
        if (dkz < 0) {
            int swap = kx;
            kx = ky;
            ky = swap;
        }
        shearX = component(kx) / dkz;
        shearY = component(ky) / dkz;
        shearZ = 1.0 / dkz;
        originKx = originComponent(kx);
        originKy = originComponent(ky);
        originKz = originComponent(kz);
    }

    private double originComponent(int axis) {
        return axis == 0 ? ox : axis == 1 ? oy : oz;
    }

    /** Direction component by axis index 0, 1, 2. */
    public double component(int axis) {
        return axis == 0 ? dx : axis == 1 ? dy : dz;
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

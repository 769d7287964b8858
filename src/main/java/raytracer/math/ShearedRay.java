package raytracer.math;

/**
 * A ray prepared for the watertight ray/triangle test (Woop, Benthin and Wald, "Watertight
 * Ray/Triangle Intersection", JCGT 2013, section 3): the axis kz along which the direction is
 * largest, the two others kx and ky (swapped when d_kz &lt; 0, to keep the triangles' winding),
 * the shear (sx, sy, sz) that takes the direction to (0, 0, 1), and the origin's coordinates on
 * kx, ky, kz. Filled from a ray by {@link #load} before its triangles are tested; a worker keeps
 * one, since triangle tests never nest.
 */
public final class ShearedRay {
    private int kx;
    private int ky;
    private int kz;
    private double sx;
    private double sy;
    private double sz;
    private double originX;
    private double originY;
    private double originZ;
    private double originError;
    private double directionError;

    /** Prepares the triangle tests of {@code ray}. */
    public ShearedRay load(Ray ray) {
        double ax = Math.abs(ray.dx);
        double ay = Math.abs(ray.dy);
        double az = Math.abs(ray.dz);
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        double dz = ray.component(kz);
        if (dz < 0) {
            int swap = kx;
            kx = ky;
            ky = swap;
        }
        sx = ray.component(kx) / dz;
        sy = ray.component(ky) / dz;
        sz = 1.0 / dz;
        originX = ray.originComponent(kx);
        originY = ray.originComponent(ky);
        originZ = ray.originComponent(kz);
        originError = ray.originError;
        directionError = ray.directionError;
        return this;
    }

    /** The axes (0, 1, 2 for x, y, z) that become the sheared frame's x, y and z. */
    public int kx() {
        return kx;
    }

    public int ky() {
        return ky;
    }

    public int kz() {
        return kz;
    }

    /** The shear: a point p relative to the origin goes to (p_kx - sx p_kz, p_ky - sy p_kz, sz p_kz). */
    public double sx() {
        return sx;
    }

    public double sy() {
        return sy;
    }

    public double sz() {
        return sz;
    }

    /** The origin's coordinate on axis kx. */
    public double originX() {
        return originX;
    }

    public double originY() {
        return originY;
    }

    public double originZ() {
        return originZ;
    }

    /** The ray's {@link Ray#originError}. */
    public double originError() {
        return originError;
    }

    /** The ray's {@link Ray#directionError}. */
    public double directionError() {
        return directionError;
    }
}

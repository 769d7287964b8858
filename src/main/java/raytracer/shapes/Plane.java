package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/** An infinite plane through a point with a normal (Suffern, section 3.7). */
public final class Plane extends GeometricObject {
    private final double ax;
    private final double ay;
    private final double az;
    private final double nx;
    private final double ny;
    private final double nz;
    /** A tangent frame (e1, e2) for texture coordinates. */
    private final Vector3D e1;
    private final Vector3D e2;

    public Plane(Point3D point, Normal normal) {
        double len = Math.sqrt(normal.x() * normal.x() + normal.y() * normal.y() + normal.z() * normal.z());
        if (!(len > 0) || !Double.isFinite(len) || !point.isFinite()) {
            throw new IllegalArgumentException("a plane needs a finite point and a non-zero normal");
        }
        ax = point.x();
        ay = point.y();
        az = point.z();
        nx = normal.x() / len;
        ny = normal.y() / len;
        nz = normal.z() / len;
        Vector3D n = new Vector3D(nx, ny, nz);
        Vector3D helper = Math.abs(nx) > 0.9 ? new Vector3D(0, 1, 0) : new Vector3D(1, 0, 0);
        e1 = helper.cross(n).normalize();
        e2 = n.cross(e1);
    }

    @Override
    public HalfSpace wholePlane() {
        return HalfSpace.through(ax, ay, az, nx, ny, nz);
    }

    private double distance(Ray ray) {
        return PlanarHit.distance(ray, ax, ay, az, nx, ny, nz);
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return recordIfCloser(distance(ray), sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return PlanarHit.crossesWithin(ray, tMax, ax, ay, az, nx, ny, nz) < tMax;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        PlanarHit.complete(ray, sr, ax, ay, az, nx, ny, nz);
        double rx = sr.hitPoint.x - ax;
        double ry = sr.hitPoint.y - ay;
        double rz = sr.hitPoint.z - az;
        sr.u = rx * e1.x() + ry * e1.y() + rz * e1.z();
        sr.v = rx * e2.x() + ry * e2.y() + rz * e2.z();
    }

    /**
     * A shadow ray from a point of the plane towards its lit side starts on that side by the hit's
     * error bound (gamma(8) times the coordinates' size), more than the rounding of the distance
     * numerator (gamma(3) of it), so its t is negative.
     */
    @Override
    public boolean cannotShadowItself() {
        return true;
    }

    @Override
    public BBox boundingBox() {
        double inf = Double.POSITIVE_INFINITY;
        // a plane normal to an axis lies exactly at its point's coordinate on that axis
        if (nx == 0 && nz == 0) {
            return new BBox(-inf, ay, -inf, inf, ay, inf);
        }
        if (ny == 0 && nz == 0) {
            return new BBox(ax, -inf, -inf, ax, inf, inf);
        }
        if (nx == 0 && ny == 0) {
            return new BBox(-inf, -inf, az, inf, inf, az);
        }
        return new BBox(-inf, -inf, -inf, inf, inf, inf);
    }
}

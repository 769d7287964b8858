package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/** A flat disk facing along its normal (Suffern, section 19.2); the visible face of a disk light. */
public final class Disk extends GeometricObject {
    private final Point3D center;
    private final Vector3D n;
    private final double radius;

    public Disk(Point3D center, Vector3D normal, double radius) {
        if (!(radius > 0) || !(normal.length() > 0) || !center.isFinite() || !normal.isFinite()) {
            throw new IllegalArgumentException("a disk needs a finite centre, a non-zero normal and a positive radius");
        }
        this.center = center;
        this.n = normal.normalize();
        this.radius = radius;
    }

    private double distance(Ray ray) {
        return inside(ray, PlanarHit.distance(ray, center.x(), center.y(), center.z(), n.x(), n.y(), n.z()));
    }

    /** t if the ray's point at t (finite) lies on the disk, else +infinity. */
    private double inside(Ray ray, double t) {
        if (t == Double.POSITIVE_INFINITY) {
            return t;
        }
        double dx = ray.atX(t) - center.x();
        double dy = ray.atY(t) - center.y();
        double dz = ray.atZ(t) - center.z();
        return dx * dx + dy * dy + dz * dz <= radius * radius ? t : Double.POSITIVE_INFINITY;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return recordIfCloser(distance(ray), sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return inside(ray, PlanarHit.crossesWithin(ray, tMax, center.x(), center.y(), center.z(), n.x(), n.y(), n.z())) < tMax;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        PlanarHit.complete(ray, sr, center.x(), center.y(), center.z(), n.x(), n.y(), n.z());
        double dx = sr.hitPoint.x - center.x();
        double dy = sr.hitPoint.y - center.y();
        double dz = sr.hitPoint.z - center.z();
        sr.u = Math.sqrt(dx * dx + dy * dy + dz * dz) / radius;
        sr.v = 0;
    }

    @Override
    public BBox boundingBox() {
        // per axis the disk reaches r sqrt(1 - n_k^2) from its centre
        double ex = radius * Math.sqrt(Math.max(0, 1 - n.x() * n.x()));
        double ey = radius * Math.sqrt(Math.max(0, 1 - n.y() * n.y()));
        double ez = radius * Math.sqrt(Math.max(0, 1 - n.z() * n.z()));
        return new BBox(center.x() - ex, center.y() - ey, center.z() - ez, center.x() + ex, center.y() + ey, center.z() + ez);
    }
}

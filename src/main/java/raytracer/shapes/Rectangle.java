package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/**
 * A parallelogram corner + u a + v b, u, v in [0, 1] (Suffern, section 18.4), with normal along
 * a x b; the visible face of a rectangle light. (u, v) are also its texture coordinates.
 */
public final class Rectangle extends GeometricObject {
    private final Point3D corner;
    private final Vector3D a;
    private final Vector3D b;
    private final Vector3D n;
    private final double area;

    public Rectangle(Point3D corner, Vector3D a, Vector3D b) {
        Vector3D cross = a.cross(b);
        if (!(cross.length() > 0) || !cross.isFinite() || !corner.isFinite()) {
            throw new IllegalArgumentException("a rectangle needs a finite corner and two non-parallel edges");
        }
        this.corner = corner;
        this.a = a;
        this.b = b;
        this.area = cross.length();
        this.n = cross.normalize();
    }

    /** t of a hit inside the parallelogram, or +infinity. */
    private double distance(Ray ray) {
        return inside(ray, PlanarHit.distance(ray, corner.x(), corner.y(), corner.z(), n.x(), n.y(), n.z()));
    }

    /** t if the ray's point at t (finite) lies in the parallelogram, else +infinity. */
    private double inside(Ray ray, double t) {
        if (t == Double.POSITIVE_INFINITY) {
            return t;
        }
        double dx = ray.atX(t) - corner.x();
        double dy = ray.atY(t) - corner.y();
        double dz = ray.atZ(t) - corner.z();
        double u = coordinate(dx, dy, dz, b, true);
        double v = coordinate(dx, dy, dz, a, false);
        return u >= 0 && u <= 1 && v >= 0 && v <= 1 ? t : Double.POSITIVE_INFINITY;
    }

    /** u = ((d x b) . n) / |a x b| and v = ((a x d) . n) / |a x b|: coordinates in the (a, b) basis. */
    private double coordinate(double dx, double dy, double dz, Vector3D e, boolean first) {
        double cx = first ? dy * e.z() - dz * e.y() : e.y() * dz - e.z() * dy;
        double cy = first ? dz * e.x() - dx * e.z() : e.z() * dx - e.x() * dz;
        double cz = first ? dx * e.y() - dy * e.x() : e.x() * dy - e.y() * dx;
        return (cx * n.x() + cy * n.y() + cz * n.z()) / area;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return recordIfCloser(distance(ray), sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return inside(ray, PlanarHit.crossesWithin(ray, tMax, corner.x(), corner.y(), corner.z(), n.x(), n.y(), n.z())) < tMax;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        PlanarHit.complete(ray, sr, corner.x(), corner.y(), corner.z(), n.x(), n.y(), n.z());
        double dx = sr.hitPoint.x - corner.x();
        double dy = sr.hitPoint.y - corner.y();
        double dz = sr.hitPoint.z - corner.z();
        sr.u = coordinate(dx, dy, dz, b, true);
        sr.v = coordinate(dx, dy, dz, a, false);
    }

    @Override
    public BBox boundingBox() {
        BBox box = BBox.EMPTY.union(corner).union(corner.add(a)).union(corner.add(b)).union(corner.add(a).add(b));
        return box;
    }
}

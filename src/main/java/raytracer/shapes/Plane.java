package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Rounding;
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

    private double distance(Ray ray) {
        double denominator = ray.dx * nx + ray.dy * ny + ray.dz * nz;
        if (denominator == 0) {
            return Double.POSITIVE_INFINITY; // parallel to the plane
        }
        return ((ax - ray.ox) * nx + (ay - ray.oy) * ny + (az - ray.oz) * nz) / denominator;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        double t = distance(ray);
        return t > 0 && recordIfCloser(t, sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        double t = distance(ray);
        return t > 0 && t < tMax;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double px = ray.atX(sr.t);
        double py = ray.atY(sr.t);
        double pz = ray.atZ(sr.t);
        // project onto the plane so the error along the normal stems from this step alone
        double off = (px - ax) * nx + (py - ay) * ny + (pz - az) * nz;
        px -= off * nx;
        py -= off * ny;
        pz -= off * nz;
        sr.hitPoint.set(px, py, pz);
        double g = Rounding.gamma(8);
        double scale = Math.abs(ax) + Math.abs(ay) + Math.abs(az) + Math.abs(px) + Math.abs(py) + Math.abs(pz);
        sr.hitError.set(g * scale, g * scale, g * scale);
        sr.normal.set(nx, ny, nz);
        sr.geometricNormal.set(nx, ny, nz);
        double rx = px - ax;
        double ry = py - ay;
        double rz = pz - az;
        sr.u = rx * e1.x() + ry * e1.y() + rz * e1.z();
        sr.v = rx * e2.x() + ry * e2.y() + rz * e2.z();
    }

    @Override
    public BBox boundingBox() {
        return new BBox(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
                        Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);
    }
}

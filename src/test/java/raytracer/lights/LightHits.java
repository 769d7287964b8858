package raytracer.lights;

import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * Where a ray from a point meets a light's surface, by plain geometry independent of the lights'
 * code: the distance along the unit direction and the cosine at the surface, or null for a miss.
 */
interface LightHits {
    double[] hit(double dx, double dy, double dz);

    /** The parallelogram corner + s a + t b, s and t in [0, 1], from p; either side. */
    static LightHits parallelogram(Point3D p, Point3D corner, Vector3D a, Vector3D b) {
        Vector3D n = a.cross(b).normalize();
        Vector3D c = new Vector3D(corner.x() - p.x(), corner.y() - p.y(), corner.z() - p.z());
        return (dx, dy, dz) -> {
            double dn = dx * n.x() + dy * n.y() + dz * n.z();
            double t = c.dot(n) / dn;
            if (!(t > 0)) {
                return null;
            }
            // the hit relative to the corner, in the (a, b) coordinates, by Cramer's rule on the plane
            Vector3D q = new Vector3D(t * dx - c.x(), t * dy - c.y(), t * dz - c.z());
            double s = q.cross(b).dot(n) / a.cross(b).dot(n);
            double r = a.cross(q).dot(n) / a.cross(b).dot(n);
            return s >= 0 && s <= 1 && r >= 0 && r <= 1 ? new double[] {t, Math.abs(dn)} : null;
        };
    }

    /** The disk of centre c, unit normal n and radius r, from p. */
    static LightHits disk(Point3D p, Point3D center, Vector3D n, double radius) {
        Vector3D c = new Vector3D(center.x() - p.x(), center.y() - p.y(), center.z() - p.z());
        return (dx, dy, dz) -> {
            double dn = dx * n.x() + dy * n.y() + dz * n.z();
            double t = c.dot(n) / dn;
            if (!(t > 0)) {
                return null;
            }
            Vector3D q = new Vector3D(t * dx - c.x(), t * dy - c.y(), t * dz - c.z());
            return q.dot(q) <= radius * radius ? new double[] {t, Math.abs(dn)} : null;
        };
    }

    /** The sphere of centre c and radius r, from p outside it: the nearer root. */
    static LightHits sphere(Point3D p, Point3D center, double r) {
        double ox = p.x() - center.x();
        double oy = p.y() - center.y();
        double oz = p.z() - center.z();
        return (dx, dy, dz) -> {
            // |o + t d|^2 = r^2
            double b = ox * dx + oy * dy + oz * dz;
            double c = ox * ox + oy * oy + oz * oz - r * r;
            double disc = b * b - c;
            if (disc < 0) {
                return null;
            }
            double t = -b - Math.sqrt(disc);
            if (!(t > 0)) {
                return null;
            }
            double cos = -((ox + t * dx) * dx + (oy + t * dy) * dy + (oz + t * dz) * dz) / r;
            return new double[] {t, cos};
        };
    }
}

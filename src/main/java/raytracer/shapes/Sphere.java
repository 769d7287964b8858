package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/** A sphere given by its centre and radius (Suffern, section 3.6). */
public final class Sphere extends GeometricObject {
    private final double cx;
    private final double cy;
    private final double cz;
    private final double radius;

    public Sphere(Point3D center, double radius) {
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("sphere radius must be a positive number, got " + radius);
        }
        if (!center.isFinite()) {
            throw new IllegalArgumentException("sphere centre must be finite, got " + center);
        }
        this.cx = center.x();
        this.cy = center.y();
        this.cz = center.z();
        this.radius = radius;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return recordIfCloser(nearestRoot(ray, sr.t), sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return nearestRoot(ray, tMax) < tMax;
    }

    /**
     * The smallest root of |o + t d - c|^2 = r^2 in (0, tMax), or +infinity. The discriminant is
     * taken as r^2 - |f - (f.d / d.d) d|^2 (Haines et al., Ray Tracing Gems, chapter 7), which keeps
     * its precision when the sphere is small and far from the ray origin.
     */
    private double nearestRoot(Ray ray, double tMax) {
        double fx = ray.ox - cx;
        double fy = ray.oy - cy;
        double fz = ray.oz - cz;
        double a = ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz;
        double halfB = fx * ray.dx + fy * ray.dy + fz * ray.dz;
        // vector from the centre to the point of the line closest to it
        double s = halfB / a;
        double lx = fx - s * ray.dx;
        double ly = fy - s * ray.dy;
        double lz = fz - s * ray.dz;
        double discriminant = radius * radius - (lx * lx + ly * ly + lz * lz);
        if (!(discriminant >= 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double c = fx * fx + fy * fy + fz * fz - radius * radius;
        // stable pair of roots: q / a and c / q (Numerical Recipes, section 5.6)
        double q = -halfB - Math.copySign(Math.sqrt(a * discriminant), halfB);
        double t0 = q / a;
        double t1 = c / q;
        double tNear = Math.min(t0, t1);
        double tFar = Math.max(t0, t1);
        if (tNear > 0 && tNear < tMax) {
            return tNear;
        }
        if (tFar > 0 && tFar < tMax) {
            return tFar;
        }
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double t = sr.t;
        double px = ray.atX(t) - cx;
        double py = ray.atY(t) - cy;
        double pz = ray.atZ(t) - cz;
        // reproject onto the surface: the error is then gamma(5) |p| (pbrt-v3, section 3.9.4)
        double scale = radius / Math.sqrt(px * px + py * py + pz * pz);
        px *= scale;
        py *= scale;
        pz *= scale;
        sr.hitPoint.set(cx + px, cy + py, cz + pz);
        double g = Rounding.gamma(6);
        sr.hitError.set(g * (Math.abs(cx) + Math.abs(px)), g * (Math.abs(cy) + Math.abs(py)),
                        g * (Math.abs(cz) + Math.abs(pz)));
        sr.normal.set(px / radius, py / radius, pz / radius);
        sr.geometricNormal.set(sr.normal);
        // spherical coordinates as in Suffern, section 29.3: u around the y axis, v from the south pole
        double phi = Math.atan2(sr.normal.x, sr.normal.z) + Math.PI;
        sr.u = phi / (2 * Math.PI);
        sr.v = 1 - Math.acos(Math.max(-1, Math.min(1, sr.normal.y))) / Math.PI;
    }

    @Override
    public BBox boundingBox() {
        return new BBox(cx - radius, cy - radius, cz - radius, cx + radius, cy + radius, cz + radius);
    }
}

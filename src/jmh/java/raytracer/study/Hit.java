package raytracer.study;

import raytracer.core.ShadeRec;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Rounding;
import raytracer.math.Vector3D;

/**
 * A completed hit as values, new for every hit: what the textbook's ShadeRec holds once the
 * closest hit is known (Suffern, section 3.5). The search and its completion ran in
 * {@code record}, a hit record of its own; that record still lends its scratch to shadow searches.
 *
 * @param wo     unit direction to the viewer
 * @param record the search's record, which instances borrow local rays from
 */
record Hit(Point3D hitPoint, Vector3D hitError, Vector3D normal, Vector3D geometricNormal, Vector3D wo, int depth,
           ShadeRec record) {

    /** The completed {@code sr} of {@code ray} as values. */
    static Hit of(ShadeRec sr, Ray ray) {
        Vector3D toViewer = new Vector3D(-ray.dx, -ray.dy, -ray.dz);
        return new Hit(new Point3D(sr.hitPoint.x, sr.hitPoint.y, sr.hitPoint.z),
                       new Vector3D(sr.hitError.x, sr.hitError.y, sr.hitError.z),
                       new Vector3D(sr.normal.x, sr.normal.y, sr.normal.z),
                       new Vector3D(sr.geometricNormal.x, sr.geometricNormal.y, sr.geometricNormal.z),
                       // times the reciprocal, as MutableVec3.normalize does, so the bits agree
                       toViewer.scale(1.0 / toViewer.length()), sr.depth, sr);
    }

    /**
     * A new ray from the hit point in direction {@code d}, its origin moved off the surface by the
     * point's error bound along the geometric normal, to the side d leaves on, and one ulp further
     * (pbrt-v3, section 3.9.5; the renderer's ShadeRec.spawnRay, in values).
     */
    Ray spawnRay(Vector3D d) {
        Vector3D n = geometricNormal;
        double offset = Math.abs(n.x()) * hitError.x() + Math.abs(n.y()) * hitError.y() + Math.abs(n.z()) * hitError.z();
        if (n.dot(d) < 0) {
            offset = -offset;
        }
        Vector3D shift = n.scale(offset);
        Point3D origin = hitPoint.add(shift);
        return new Ray().set(nudge(origin.x(), shift.x()), nudge(origin.y(), shift.y()), nudge(origin.z(), shift.z()),
                             d.x(), d.y(), d.z());
    }

    /**
     * A new ray from the hit point, moved off as {@link #spawnRay} moves it, aimed at {@code q}: its
     * direction q - origin reaches q at t = 1, and the subtraction's rounding is its direction
     * error (the renderer's ShadeRec.spawnRayTo, in values).
     */
    Ray spawnRayTo(Point3D q) {
        Ray from = spawnRay(q.sub(hitPoint));
        double dx = q.x() - from.ox;
        double dy = q.y() - from.oy;
        double dz = q.z() - from.oz;
        double largest = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
        return new Ray().set(from.ox, from.oy, from.oz, dx, dy, dz).setErrors(0, Rounding.gamma(1) * largest);
    }

    private static double nudge(double value, double offset) {
        if (offset > 0) {
            return Math.nextUp(value);
        }
        if (offset < 0) {
            return Math.nextDown(value);
        }
        return value;
    }
}

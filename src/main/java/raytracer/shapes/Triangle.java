package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.ShearedRay;
import raytracer.math.Vector3D;

/** A single flat triangle (Suffern, section 19.3), hit by the watertight test of {@link Watertight}. */
public final class Triangle extends GeometricObject {
    /**
     * The largest magnitude a vertex coordinate may have, as {@link Sphere}'s extent is bounded: the
     * normal is the cross product of two edges (each component up to 8 c^2 for coordinates up to c),
     * whose squared length must stay below the largest double, 1.8e308, or it normalises to 0 and
     * the triangle renders unlit (from c = 1e77; the watertight test's products overflow from 1e154).
     */
    public static final double MAX_COORDINATE = 1e75;
    private final double[] v = new double[9];
    private final Vector3D normal;
    private final boolean degenerate;

    public Triangle(Point3D a, Point3D b, Point3D c) {
        if (!a.isFinite() || !b.isFinite() || !c.isFinite()) {
            throw new IllegalArgumentException("triangle vertices must be finite");
        }
        double largest = 0;
        for (Point3D p : new Point3D[] {a, b, c}) {
            largest = Math.max(largest, Math.max(Math.abs(p.x()), Math.max(Math.abs(p.y()), Math.abs(p.z()))));
        }
        if (largest > MAX_COORDINATE) {
            throw new IllegalArgumentException("triangle vertex coordinates must be at most " + MAX_COORDINATE + " in size (the "
                                               + "cross product of two edges must square to a double), got " + largest);
        }
        Point3D[] p = {a, b, c};
        for (int i = 0; i < 3; i++) {
            v[3 * i] = p[i].x();
            v[3 * i + 1] = p[i].y();
            v[3 * i + 2] = p[i].z();
        }
        Vector3D e1 = b.sub(a);
        Vector3D e2 = c.sub(a);
        Vector3D n = e1.cross(e2);
        degenerate = Watertight.isDegenerate(e1, e2, n);
        normal = degenerate ? Vector3D.UP : n.normalize();
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        if (degenerate) {
            return false;
        }
        ShearedRay sheared = sr.scratch.shearedRay.load(ray);
        return recordIfCloser(Watertight.intersect(sheared, v, 0, 3, 6, sr.t, sr), sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return !degenerate && Watertight.crossesWithin(sr.scratch.shearedRay.load(ray), v, 0, 3, 6, tMax);
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double b1 = sr.b1;
        double b2 = sr.b2;
        double b0 = 1 - b1 - b2;
        Watertight.interpolate(v, 0, 3, 6, b0, b1, b2, sr);
        sr.normal.set(normal.x(), normal.y(), normal.z());
        sr.geometricNormal.set(sr.normal);
        sr.u = b1;
        sr.v = b2;
    }

    @Override
    public BBox boundingBox() {
        return new BBox(
            Math.min(v[0], Math.min(v[3], v[6])), Math.min(v[1], Math.min(v[4], v[7])),
            Math.min(v[2], Math.min(v[5], v[8])), Math.max(v[0], Math.max(v[3], v[6])),
            Math.max(v[1], Math.max(v[4], v[7])), Math.max(v[2], Math.max(v[5], v[8])));
    }
}

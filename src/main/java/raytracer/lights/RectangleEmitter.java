package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Rounding;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/** A parallelogram corner + u a + v b; it emits on the side of a x b. */
final class RectangleEmitter implements Emitter {
    private final Point3D corner;
    private final Vector3D a;
    private final Vector3D b;
    private final Vector3D normal;
    private final double area;
    /** The move off the emitter along the normal ({@link #moveOff}), the same for every sample. */
    private final double offX;
    private final double offY;
    private final double offZ;

    RectangleEmitter(Point3D corner, Vector3D a, Vector3D b) {
        Vector3D n = a.cross(b);
        if (!(n.length() > 0) || !n.isFinite()) {
            throw new IllegalArgumentException("a rectangle light needs two non-parallel edges");
        }
        this.corner = corner;
        this.a = a;
        this.b = b;
        this.area = n.length();
        this.normal = n.normalize();
        // corner + u a + v b with u, v in [0, 1): two products and two sums per axis, gamma(4) of
        // the largest sum of magnitudes; projected on the normal, plus two ulps of the largest
        // coordinate, so that adding the move cannot round it away
        double largest = Math.max(Math.abs(corner.x()) + Math.abs(a.x()) + Math.abs(b.x()),
                                  Math.max(Math.abs(corner.y()) + Math.abs(a.y()) + Math.abs(b.y()),
                                           Math.abs(corner.z()) + Math.abs(a.z()) + Math.abs(b.z())));
        Vector3D u = normal;
        double move = Rounding.gamma(4) * largest * (Math.abs(u.x()) + Math.abs(u.y()) + Math.abs(u.z())) + 0x1.0p-51 * largest;
        this.offX = move * u.x();
        this.offY = move * u.y();
        this.offZ = move * u.z();
    }

    @Override
    public void moveOff(MutableVec3 point, MutableVec3 n) {
        point.set(point.x + offX, point.y + offY, point.z + offZ);
    }

    @Override
    public void sample(double u, double v, MutableVec3 point, MutableVec3 n) {
        point.set(corner.x() + u * a.x() + v * b.x(), corner.y() + u * a.y() + v * b.y(), corner.z() + u * a.z() + v * b.z());
        n.set(normal.x(), normal.y(), normal.z());
    }

    @Override
    public boolean mayLight(MutableVec3 p, MutableVec3 n) {
        double cx = corner.x() - p.x;
        double cy = corner.y() - p.y;
        double cz = corner.z() - p.z;
        if (normal.x() * cx + normal.y() * cy + normal.z() * cz >= 0) {
            return false; // p is not in front of the emitting side
        }
        // the corner with the largest height over the tangent plane (n . (q - p) is linear in u, v)
        double h = n.x * cx + n.y * cy + n.z * cz;
        double ha = n.x * a.x() + n.y * a.y() + n.z * a.z();
        double hb = n.x * b.x() + n.y * b.y() + n.z * b.z();
        // h + max(ha, 0) + max(hb, 0) > 0, without Math.max's NaN and -0.0 rules (a long blend
        // sequence); adding a zero could only change the sign of a zero sum, which fails "> 0"
        // either way, and a NaN height still answers false
        double top = h;
        if (ha > 0) {
            top += ha;
        }
        if (hb > 0) {
            top += hb;
        }
        return top > 0 && !Double.isNaN(ha) && !Double.isNaN(hb);
    }

    @Override
    public BBox bounds() {
        Point3D far = new Point3D(corner.x() + a.x() + b.x(), corner.y() + a.y() + b.y(), corner.z() + a.z() + b.z());
        return BBox.EMPTY.union(corner).union(far)
                   .union(new Point3D(corner.x() + a.x(), corner.y() + a.y(), corner.z() + a.z()))
                   .union(new Point3D(corner.x() + b.x(), corner.y() + b.y(), corner.z() + b.z()));
    }

    @Override
    public double area() {
        return area;
    }
}

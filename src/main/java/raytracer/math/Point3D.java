package raytracer.math;

/** An immutable position. Points and vectors differ under translation (see {@link Matrix4}). */
public record Point3D(double x, double y, double z) {

    public static final Point3D ORIGIN = new Point3D(0, 0, 0);

    public Point3D add(Vector3D v) {
        return new Point3D(x + v.x(), y + v.y(), z + v.z());
    }

    /** The vector from {@code p} to this point. */
    public Vector3D sub(Point3D p) {
        return new Vector3D(x - p.x, y - p.y, z - p.z);
    }

    public double distance(Point3D p) {
        return sub(p).length();
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }
}

package raytracer.math;

/** An immutable axis-aligned bounding box; {@link #EMPTY} is the identity of {@link #union}. */
public record BBox(double x0, double y0, double z0, double x1, double y1, double z1) {

    public static final BBox EMPTY = new BBox(
        Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
        Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY);

    public BBox union(BBox b) {
        return new BBox(Math.min(x0, b.x0), Math.min(y0, b.y0), Math.min(z0, b.z0),
                        Math.max(x1, b.x1), Math.max(y1, b.y1), Math.max(z1, b.z1));
    }

    public BBox union(Point3D p) {
        return new BBox(Math.min(x0, p.x()), Math.min(y0, p.y()), Math.min(z0, p.z()),
                        Math.max(x1, p.x()), Math.max(y1, p.y()), Math.max(z1, p.z()));
    }

    public boolean isEmpty() {
        return x0 > x1 || y0 > y1 || z0 > z1;
    }

    public boolean isBounded() {
        return Double.isFinite(x0) && Double.isFinite(y0) && Double.isFinite(z0)
            && Double.isFinite(x1) && Double.isFinite(y1) && Double.isFinite(z1);
    }

    public boolean contains(double x, double y, double z) {
        return x >= x0 && x <= x1 && y >= y0 && y <= y1 && z >= z0 && z <= z1;
    }

    public Point3D center() {
        return new Point3D(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1));
    }

    /** 0, 1 or 2 for the axis along which the box is longest. */
    public int longestAxis() {
        double ex = x1 - x0;
        double ey = y1 - y0;
        double ez = z1 - z0;
        return ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
    }

    public double surfaceArea() {
        double ex = x1 - x0;
        double ey = y1 - y0;
        double ez = z1 - z0;
        return 2 * (ex * ey + ey * ez + ez * ex);
    }

    /** The largest absolute coordinate of the box, the scale against which rounding errors are judged. */
    public double maxAbs() {
        return Math.max(Math.max(Math.max(Math.abs(x0), Math.abs(x1)), Math.max(Math.abs(y0), Math.abs(y1))),
                        Math.max(Math.abs(z0), Math.abs(z1)));
    }
}

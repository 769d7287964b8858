package raytracer.math;

/**
 * The closed half-space of the points p with n . p &lt;= d: one side of a plane, as the scene
 * analysis uses them to prove that no ray can reach an object (a face of the camera's view
 * volume, or a plane separating an object from what it could shadow).
 */
public record HalfSpace(double nx, double ny, double nz, double d) {
    /**
     * How far past its plane a box must lie, relative to the size of the coordinates involved, to
     * count as strictly outside: 2^-30 (about 1e-9), a million times the few ulps by which a
     * computed ray or hit point can stray from its exact value, so that no rounding can carry a
     * ray across it.
     */
    public static final double MARGIN = 0x1.0p-30;

    public HalfSpace {
        if (!Double.isFinite(nx) || !Double.isFinite(ny) || !Double.isFinite(nz) || !Double.isFinite(d)
            || nx == 0 && ny == 0 && nz == 0) {
            throw new IllegalArgumentException("a half-space needs a finite, non-zero normal and a finite offset");
        }
    }

    /** The half-space n . (p - point) &lt;= 0: bounded by the plane through {@code point}, normal n pointing out. */
    public static HalfSpace through(double px, double py, double pz, double nx, double ny, double nz) {
        return new HalfSpace(nx, ny, nz, nx * px + ny * py + nz * pz);
    }

    /** The other side: the closed half-space n . p &gt;= d, as -n . p &lt;= -d. */
    public HalfSpace flipped() {
        return new HalfSpace(-nx, -ny, -nz, -d);
    }

    /** True when the point lies in the closed half-space (on its plane counts). */
    public boolean contains(double x, double y, double z) {
        return nx * x + ny * y + nz * z <= d;
    }

    /** True when every corner of the box lies in the closed half-space; an unbounded box is never inside. */
    public boolean contains(BBox box) {
        return box.isBounded() && extreme(box, false) <= d;
    }

    /**
     * True when the whole box lies outside, past the plane by more than {@link #MARGIN} times the
     * size of the numbers in n . p and d; an unbounded box never does.
     */
    public boolean excludes(BBox box) {
        if (!box.isBounded()) {
            return false;
        }
        double scale = (Math.abs(nx) + Math.abs(ny) + Math.abs(nz)) * box.maxAbs() + Math.abs(d);
        return extreme(box, true) - d > MARGIN * scale;
    }

    /** n . p over the box's corners: the smallest (lowest) or the largest. */
    private double extreme(BBox box, boolean lowest) {
        double x = (nx >= 0) == lowest ? box.x0() : box.x1();
        double y = (ny >= 0) == lowest ? box.y0() : box.y1();
        double z = (nz >= 0) == lowest ? box.z0() : box.z1();
        return nx * x + ny * y + nz * z;
    }
}

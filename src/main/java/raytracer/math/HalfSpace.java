package raytracer.math;

/**
 * The closed half-space of the points p with n . p &lt;= d: one side of a plane, as the scene
 * analysis uses them to prove that no ray can reach an object (a face of the camera's view
 * volume, or a plane separating an object from what it could shadow). {@code size} is the
 * largest coordinate that d, or the rays it bounds, were computed from (the camera's eye, a point
 * of the plane); the margin of {@link #excludes} is taken relative to it as well, since d's
 * rounding, and a computed ray's, grow with it even where n . p cancels.
 */
public record HalfSpace(double nx, double ny, double nz, double d, double size) {
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
        if (!(size >= 0) || !Double.isFinite(size)) {
            throw new IllegalArgumentException("a half-space's size must be finite and 0 or more, got " + size);
        }
    }

    /** n . p &lt;= d with d exact (an axis-aligned plane at a given coordinate). */
    public HalfSpace(double nx, double ny, double nz, double d) {
        this(nx, ny, nz, d, 0);
    }

    /** The half-space n . (p - point) &lt;= 0: bounded by the plane through {@code point}, normal n pointing out. */
    public static HalfSpace through(double px, double py, double pz, double nx, double ny, double nz) {
        return new HalfSpace(nx, ny, nz, nx * px + ny * py + nz * pz, Math.max(Math.abs(px), Math.max(Math.abs(py), Math.abs(pz))));
    }

    /** The other side: the closed half-space n . p &gt;= d, as -n . p &lt;= -d. */
    public HalfSpace flipped() {
        return new HalfSpace(-nx, -ny, -nz, -d, size);
    }

    /** The same half-space, its margin taken relative to coordinates as large as {@code s} too. */
    public HalfSpace atScale(double s) {
        return new HalfSpace(nx, ny, nz, d, Math.max(size, s));
    }

    /** True when the plane is perpendicular to an axis: one component of n is not zero. */
    public boolean isAxisAligned() {
        return (nx != 0 ? 1 : 0) + (ny != 0 ? 1 : 0) + (nz != 0 ? 1 : 0) == 1;
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
     * size of the numbers in n . p and d (the box's coordinates or {@link #size}, whichever is
     * larger); an unbounded box never does.
     */
    public boolean excludes(BBox box) {
        if (!box.isBounded()) {
            return false;
        }
        double scale = (Math.abs(nx) + Math.abs(ny) + Math.abs(nz)) * Math.max(box.maxAbs(), size) + Math.abs(d);
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

package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Rounding;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * A parallelogram corner + u a + v b; it emits on the side of a x b. A rectangle (a . b = 0, to
 * 1e-9 of |a| |b|) is sampled uniformly over the solid angle it covers at the shaded point
 * ({@link SphericalRectangle}) where it is near or large ({@link #nearOrLarge}) and that solid
 * angle at least {@link SphericalRectangle#MIN_SOLID_ANGLE}; elsewhere, and a parallelogram that is
 * not a rectangle everywhere, it is sampled uniformly by area, the corner plus u a plus v b.
 */
final class RectangleEmitter implements Emitter {
    /** How far from perpendicular the edges may be for the light to count as a rectangle, as a cosine. */
    private static final double RIGHT_ANGLE_TOLERANCE = 1e-9;
    /** The ratio of squared distances above which a rectangle is sampled by solid angle ({@link #nearOrLarge}). */
    static final double NEAR_OR_LARGE = 2;

    private final Point3D corner;
    private final Vector3D a;
    private final Vector3D b;
    private final Vector3D normal;
    private final double area;
    private final double inverseArea;
    /** True when a and b are perpendicular: then sampled by solid angle. */
    private final boolean rectangle;
    /** The rectangle's frame: ex along a, ey = normal x ex along b, and the edges' lengths along them. */
    private final Vector3D ex;
    private final Vector3D ey;
    private final double width;
    private final double height;
    private final double inverseWidth;
    private final double inverseHeight;
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
        this.inverseArea = 1 / area;
        this.normal = n.normalize();
        this.rectangle = Math.abs(a.dot(b)) <= RIGHT_ANGLE_TOLERANCE * a.length() * b.length();
        this.ex = a.normalize();
        this.ey = normal.cross(ex);
        this.width = a.length();
        this.height = b.dot(ey);
        this.inverseWidth = 1 / width;
        this.inverseHeight = 1 / height;
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

    /**
     * By solid angle where {@link #solidAngle} allows it: the spherical rectangle's point, as the
     * fractions of the edges it lies at, becomes corner + s a + t b, the same sum as a sample by
     * area, so that {@link #moveOff}'s bound holds for it. Its area density is
     * pdf_omega cos(theta_light) / d^2 with pdf_omega = 1 / solid angle.
     */
    @Override
    public double sample(MutableVec3 p, double u, double v, MutableVec3 point, MutableVec3 n) {
        n.set(normal.x(), normal.y(), normal.z());
        if (rectangle) {
            double cx = corner.x() - p.x;
            double cy = corner.y() - p.y;
            double cz = corner.z() - p.z;
            // the corner in the frame (ex, ey, normal) at p, the normal turned towards p, over a
            // length at least the largest coordinate so that no product overflows
            double x0 = cx * ex.x() + cy * ex.y() + cz * ex.z();
            double y0 = cx * ey.x() + cy * ey.y() + cz * ey.z();
            double z0 = -Math.abs(cx * normal.x() + cy * normal.y() + cz * normal.z());
            double length = Math.abs(x0) + Math.abs(y0) - z0 + width + height;
            double scale = 1 / length;
            x0 *= scale;
            y0 *= scale;
            z0 *= scale;
            double x1 = x0 + width * scale;
            double y1 = y0 + height * scale;
            if (z0 < 0 && nearOrLarge(x0, y0, x1, y1, z0)) {
                double k = SphericalRectangle.edgeAngle(x0, y0, y1, z0);
                double solidAngle = k - SphericalRectangle.edgeAngle(x1, y0, y1, z0);
                if (solidAngle >= SphericalRectangle.MIN_SOLID_ANGLE) {
                    SphericalRectangle.sample(x0, y0, x1, y1, z0, solidAngle, k, u, v, point);
                    double s = (point.x - x0) * length * inverseWidth;
                    double t = (point.y - y0) * length * inverseHeight;
                    point.set(corner.x() + s * a.x() + t * b.x(), corner.y() + s * a.y() + t * b.y(),
                              corner.z() + s * a.z() + t * b.z());
                    double g = Emitter.geometricFactor(p, point, n);
                    // a point that faces away only by rounding has G = 0 and weighs nothing
                    return g > 0 ? g / solidAngle : inverseArea;
                }
            }
        }
        point.set(corner.x() + u * a.x() + v * b.x(), corner.y() + u * a.y() + v * b.y(), corner.z() + u * a.z() + v * b.z());
        return inverseArea;
    }

    @Override
    public double pdf(double px, double py, double pz, double distance, double cosLight) {
        double solidAngle = solidAngle(px, py, pz);
        return solidAngle > 0 ? cosLight / (distance * distance * solidAngle) : inverseArea;
    }

    /**
     * The solid angle the rectangle covers at p, as {@link #sample} computes it, where it samples
     * by solid angle; 0 where it samples by area.
     */
    private double solidAngle(double px, double py, double pz) {
        if (!rectangle) {
            return 0;
        }
        double cx = corner.x() - px;
        double cy = corner.y() - py;
        double cz = corner.z() - pz;
        double x0 = cx * ex.x() + cy * ex.y() + cz * ex.z();
        double y0 = cx * ey.x() + cy * ey.y() + cz * ey.z();
        double z0 = -Math.abs(cx * normal.x() + cy * normal.y() + cz * normal.z());
        double scale = 1 / (Math.abs(x0) + Math.abs(y0) - z0 + width + height);
        x0 *= scale;
        y0 *= scale;
        z0 *= scale;
        double x1 = x0 + width * scale;
        double y1 = y0 + height * scale;
        if (!nearOrLarge(x0, y0, x1, y1, z0)) {
            return 0;
        }
        double solidAngle = SphericalRectangle.solidAngle(x0, y0, x1, y1, z0);
        return solidAngle >= SphericalRectangle.MIN_SOLID_ANGLE ? solidAngle : 0;
    }

    /**
     * True where sampling by area would weigh its samples unevenly, so that sampling by solid angle
     * pays for its cost (about twice that of a sample by area and its shading): the weight of a
     * sample by area, A cos(theta_light) / d^2 = A |z0| / d^3, varies across the rectangle as
     * (d_far / d_near)^3, d_near the distance to its nearest point and d_far to its farthest
     * corner; below {@link #NEAR_OR_LARGE} in d^2 (a factor 2.8 in the weight) the rectangle is
     * sampled by area. Measured: at 2 the area-light spheres' time to an error is what it was by area
     * and the closed-form rectangle's 2.5 times shorter; at 1.5 the latter's 21 times shorter but the
     * former's 1.4 times longer, its shadows, not the light's weights, being the error there.
     * In the rectangle's frame at the point, any scale.
     */
    static boolean nearOrLarge(double x0, double y0, double x1, double y1, double z0) {
        double dx = x0 > 0 ? x0 : x1 < 0 ? -x1 : 0;
        double dy = y0 > 0 ? y0 : y1 < 0 ? -y1 : 0;
        double near = z0 * z0 + dx * dx + dy * dy;
        double far = z0 * z0 + Math.max(x0 * x0, x1 * x1) + Math.max(y0 * y0, y1 * y1);
        return far > NEAR_OR_LARGE * near;
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

package raytracer.lights;

import java.util.List;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Rounding;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * A parallelogram corner + u a + v b; it emits on the side of a x b. A rectangle (a . b = 0, to
 * 1e-9 of |a| |b|) is sampled uniformly over the solid angle it covers at the shaded point
 * ({@link SphericalRectangle}) if some object lies near it ({@link #prepare}), and that solid
 * angle is at least {@link SphericalRectangle#MIN_SOLID_ANGLE}; otherwise, and a parallelogram that
 * is not a rectangle everywhere, it is sampled uniformly by area, the corner plus u a plus v b.
 *
 * <p>By solid angle a sample costs about twice what it does by area, and gains only where the
 * weights by area, A cos(theta_light) / d^2, vary much across the light: near it. The choice is
 * made once per light and frame, not per point: where two maps of the pixel's stratified sample
 * values meet in one pixel, neither keeps its strata, and a seam of noisy pixels shows (measured
 * with the choice made per point at a ratio of 2 in squared distance: the closed-form rectangle's
 * worst pixel at 256 spp 0.019 off, against 0.00025 by solid angle throughout). The one switch per
 * point left, at the smallest solid angle, is where the light covers at most 1e-5 sr.
 */
final class RectangleEmitter implements Emitter {
    /** How far from perpendicular the edges may be for the light to count as a rectangle, as a cosine. */
    private static final double RIGHT_ANGLE_TOLERANCE = 1e-9;
    /**
     * The squared ratio of the farthest corner's distance to the nearest point's, at some point an
     * object may hold, above which the light is sampled by solid angle: sqrt(3) in distance, the
     * weights by area varying 5.2 times across the light there. Measured: the area-light spheres
     * (at most 2.4, at the corners of the spheres' boxes) lost 1.7 times in time to an error by
     * solid angle, the closed-form rectangle (up to 3.5 and more) gained 2 to 3 times.
     */
    static final double NEAR = 3;
    /** Points per axis at which {@link #prepare} looks into each object's box. */
    private static final int GRID = 9;

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
    /** Chosen by {@link #prepare}; for a rectangle, by solid angle until then. */
    private boolean bySolidAngle;
    /** Set by {@link #fix}: {@link #prepare} leaves the choice as it is. */
    private boolean fixed;

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
        this.bySolidAngle = rectangle;
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
        if (bySolidAngle) {
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
            if (z0 < 0) {
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
        if (!bySolidAngle) {
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
        double solidAngle = SphericalRectangle.solidAngle(x0, y0, x1, y1, z0);
        return solidAngle >= SphericalRectangle.MIN_SOLID_ANGLE ? solidAngle : 0;
    }

    /**
     * By solid angle if the light is near some object: if at a point of some object's box, in
     * front of the light, its farthest corner is more than sqrt(3) times as far as its nearest point
     * ({@link #NEAR}). Beyond twice the light's width plus height from its bounds no point can be
     * (the farthest corner is then at most 1.5 times as far), so each box is clipped to that
     * reach and looked at in a grid of {@link #GRID}^3 points: a heuristic that decides only the
     * noise, never the mean. Points within 1e-6 of the light's size of its plane (the light's own
     * visible surface) receive nothing from it and are not counted.
     */
    @Override
    public void prepare(List<BBox> receivers) {
        if (fixed) {
            return;
        }
        bySolidAngle = false;
        if (!rectangle) {
            return;
        }
        double size = width + height;
        double reach = 2 * size;
        BBox own = bounds();
        for (BBox box : receivers) {
            double xa = Math.max(box.x0(), own.x0() - reach);
            double ya = Math.max(box.y0(), own.y0() - reach);
            double za = Math.max(box.z0(), own.z0() - reach);
            double xb = Math.min(box.x1(), own.x1() + reach);
            double yb = Math.min(box.y1(), own.y1() + reach);
            double zb = Math.min(box.z1(), own.z1() + reach);
            if (!(xa <= xb && ya <= yb && za <= zb)) {
                continue;
            }
            for (int i = 0; i < GRID; i++) {
                for (int j = 0; j < GRID; j++) {
                    for (int k = 0; k < GRID; k++) {
                        double t = 1.0 / (GRID - 1);
                        if (near(xa + i * t * (xb - xa), ya + j * t * (yb - ya), za + k * t * (zb - za), size)) {
                            bySolidAngle = true;
                            return;
                        }
                    }
                }
            }
        }
    }

    /** Samples by solid angle or by area whatever lies near. */
    void fix(boolean solidAngle) {
        if (solidAngle && !rectangle) {
            throw new IllegalArgumentException("a parallelogram whose edges are not perpendicular is sampled by area only");
        }
        bySolidAngle = solidAngle;
        fixed = true;
    }

    /** Whether the light at (px, py, pz), in front of it, spreads over more than {@link #NEAR} in squared distance. */
    private boolean near(double px, double py, double pz, double size) {
        double cx = corner.x() - px;
        double cy = corner.y() - py;
        double cz = corner.z() - pz;
        double z0 = cx * normal.x() + cy * normal.y() + cz * normal.z();
        if (!(z0 < -1e-6 * size)) {
            return false;
        }
        double x0 = cx * ex.x() + cy * ex.y() + cz * ex.z();
        double y0 = cx * ey.x() + cy * ey.y() + cz * ey.z();
        double x1 = x0 + width;
        double y1 = y0 + height;
        double dx = x0 > 0 ? x0 : x1 < 0 ? -x1 : 0;
        double dy = y0 > 0 ? y0 : y1 < 0 ? -y1 : 0;
        double nearest = z0 * z0 + dx * dx + dy * dy;
        double farthest = z0 * z0 + Math.max(x0 * x0, x1 * x1) + Math.max(y0 * y0, y1 * y1);
        return farthest > NEAR * nearest;
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

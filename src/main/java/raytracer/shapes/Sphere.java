package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.Skipped;
import raytracer.math.BBox;
import raytracer.math.Compensated;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/** A sphere given by its centre and radius (Suffern, section 3.6). */
public final class Sphere extends GeometricObject {
    /**
     * c = |f|^2 - r^2 is off by at most gamma(8) (|f|^2 + r^2); below 2^26 times that it is
     * recomputed from the exact o - c to about twice double precision, so it keeps at least 26
     * correct bits wherever double-double arithmetic can give them.
     */
    private static final double C_RECOMPUTE = 0x1.0p26 * Rounding.gamma(8);
    /**
     * The farthest a sphere may reach from the origin: the square of a distance to it then stays
     * far below the largest double, 1.8e308 (radius 1e160 rendered black: r^2 was infinite).
     */
    static final double MAX_EXTENT = 1e150;
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
        double extent = Math.max(Math.abs(center.x()), Math.max(Math.abs(center.y()), Math.abs(center.z()))) + radius;
        if (extent > MAX_EXTENT) {
            throw new IllegalArgumentException("sphere radius plus centre coordinate must be at most " + MAX_EXTENT
                                               + " (squared distances to it must be doubles), got " + extent);
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

    /**
     * True when the ray crosses the sphere in (0, tMax), unless each crossing found there is shown
     * to lie within rounding of an end ({@link #touchesAnEnd}): a sphere through the light's point
     * touches the shadow ray's end and does not block it. A ray whose two crossings both lie
     * between its ends passes through the ball there and is blocked without that test: the usual
     * case of a sphere casting a shadow.
     */
    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        // the roots as nearestRoot finds them
        double fx = ray.ox - cx;
        double fy = ray.oy - cy;
        double fz = ray.oz - cz;
        double a = ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz;
        double halfB = fx * ray.dx + fy * ray.dy + fz * ray.dz;
        double s = halfB / a;
        double lx = fx - s * ray.dx;
        double ly = fy - s * ray.dy;
        double lz = fz - s * ray.dz;
        double r2 = radius * radius;
        double discriminant = r2 - (lx * lx + ly * ly + lz * lz);
        if (!(discriminant > 0)) {
            return false;
        }
        double ff = fx * fx + fy * fy + fz * fz;
        double c = ff - r2;
        if (Math.abs(c) < C_RECOMPUTE * (ff + r2)) {
            c = exactC(ray);
        }
        double q = -halfB - Math.copySign(Math.sqrt(a * discriminant), halfB);
        double t0 = q / a;
        double t1 = c / q;
        double tNear = Math.min(t0, t1);
        double tFar = Math.max(t0, t1);
        boolean nearWithin = tNear > 0 && tNear < tMax;
        boolean farWithin = tFar > 0 && tFar < tMax;
        if (nearWithin && farWithin) {
            return true;
        }
        return nearWithin ? !touchesAnEnd(ray, tNear, tMax) : farWithin && !touchesAnEnd(ray, tFar, tMax);
    }

    /**
     * True when the crossing at {@code t} is certainly within rounding of 0 or of {@code tMax}.
     * With p = o + t d - c, g(t) = |p|^2 - r^2 vanishes at the exact crossing; its slope is
     * 2 p . d, so the exact root lies within 2 |g| / |slope| of t when the curvature a = d . d
     * cannot undo that (2 a delta < |slope|: at t + delta the quadratic has g's opposite sign). |g| is taken with its error bound,
     * first plainly, then compensated ({@link Compensated}) if that leaves t undecided, and the
     * ray's own errors move g by 2 |p|_1 (originError + t directionError). When the slope's sign
     * is not certain (a tangent ray, or a sphere so large against the ray's length that p is all
     * rounding) nothing is shown, and the crossing counts.
     */
    private boolean touchesAnEnd(Ray ray, double t, double tMax) {
        double px = ray.atX(t) - cx;
        double py = ray.atY(t) - cy;
        double pz = ray.atZ(t) - cz;
        // |p_i - exact| <= gamma(3) (|o_i| + |t d_i| + |c_i|)
        double g3 = Rounding.gamma(3);
        double ex = g3 * (Math.abs(ray.ox) + Math.abs(t * ray.dx) + Math.abs(cx));
        double ey = g3 * (Math.abs(ray.oy) + Math.abs(t * ray.dy) + Math.abs(cy));
        double ez = g3 * (Math.abs(ray.oz) + Math.abs(t * ray.dz) + Math.abs(cz));
        double pd = px * ray.dx + py * ray.dy + pz * ray.dz;
        double pdError = g3 * (Math.abs(px * ray.dx) + Math.abs(py * ray.dy) + Math.abs(pz * ray.dz))
                         + ex * Math.abs(ray.dx) + ey * Math.abs(ray.dy) + ez * Math.abs(ray.dz);
        double slope = 2 * (Math.abs(pd) - pdError);
        if (!(slope > 0)) {
            return false;
        }
        double p1 = Math.abs(px) + Math.abs(py) + Math.abs(pz);
        double moved = 2 * (p1 + ex + ey + ez) * (ray.originError + t * ray.directionError);
        double pp = px * px + py * py + pz * pz;
        double plain = Math.abs(pp - radius * radius) + Rounding.gamma(4) * (pp + radius * radius)
                       + 2 * (Math.abs(px) * ex + Math.abs(py) * ey + Math.abs(pz) * ez) + ex * ex + ey * ey + ez * ez;
        double a = ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz;
        if (within(t, tMax, 2 * (plain + moved) / slope, a, slope)) {
            return true;
        }
        double g = Compensated.residual(ray.ox, ray.oy, ray.oz, t, ray.dx, ray.dy, ray.dz, cx, cy, cz, radius);
        double length = Math.sqrt(pp);
        double compensated = Math.abs(g) + Compensated.errorBound(g, length, radius);
        return within(t, tMax, 2 * (compensated + moved) / slope, a, slope);
    }

    /** True when {@code t} lies within {@code delta} of 0 or tMax, and the curvature a cannot spoil that bound. */
    private static boolean within(double t, double tMax, double delta, double a, double slope) {
        return 2 * a * delta < slope && (t <= delta || tMax - t <= delta);
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
        double r2 = radius * radius;
        double discriminant = r2 - (lx * lx + ly * ly + lz * lz);
        // a double root is a tangent ray, touching without crossing: no hit (ShadeRec.complete). It
        // is refused here, where it is exact: a nonzero discriminant is at least about an ulp of
        // r^2, so the near root lies before the line's closest approach by some 1e-8 r, more than
        // the hit point's rounding for rays from within millions of radii, and its normal faces the
        // ray; at a double root the normal may lean either way (it was taken as a back face)
        if (!(discriminant > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double ff = fx * fx + fy * fy + fz * fz;
        double c = ff - r2;
        // c, which fixes the near root, cancels when the origin is close to the surface against the
        // radius: 1 unit above a sphere of radius 1e16 no digit was left and the near root was lost
        if (Math.abs(c) < C_RECOMPUTE * (ff + r2)) {
            c = exactC(ray);
        }
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

    /** c from the exact o - c (its own method, so that nearestRoot stays small enough to be inlined). */
    private double exactC(Ray ray) {
        return Compensated.residual(ray.ox, ray.oy, ray.oz, 0, ray.dx, ray.dy, ray.dz, cx, cy, cz, radius);
    }

    /**
     * The hit point is taken in one of two ways, whichever has the smaller error bound along the
     * normal. Reprojected from the centre onto the surface, it is off by at most gamma(5) |p| plus
     * the rounding of c + p (pbrt-v3, section 3.9.4): best for a sphere near the origin. On the ray,
     * o + t d after one Newton step on the compensated residual g(t) = |o + t d - c|^2 - r^2, it is
     * off by gamma(2) (|o| + |t d|) plus its distance from the surface, |g| / (|p| + r): best for
     * a sphere that is large against its distance from the ray's origin, where |c| is huge and the
     * first bound with it (radius 1e20: 1e5 units, and every shadow ray would start above the
     * occluders it should meet).
     */
    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double t = sr.t;
        double px = ray.atX(t) - cx;
        double py = ray.atY(t) - cy;
        double pz = ray.atZ(t) - cz;
        double length = Math.sqrt(px * px + py * py + pz * pz);
        double nx = px / length;
        double ny = py / length;
        double nz = pz / length;
        double g6 = Rounding.gamma(6);
        double reprojected = g6 * (Math.abs(nx) * (Math.abs(cx) + Math.abs(px)) + Math.abs(ny) * (Math.abs(cy) + Math.abs(py))
                                   + Math.abs(nz) * (Math.abs(cz) + Math.abs(pz)));
        double g2 = Rounding.gamma(2);
        double onRay = g2 * (Math.abs(nx) * (Math.abs(ray.ox) + Math.abs(t * ray.dx)) + Math.abs(ny) * (Math.abs(ray.oy)
                             + Math.abs(t * ray.dy)) + Math.abs(nz) * (Math.abs(ray.oz) + Math.abs(t * ray.dz)));
        if (!(onRay < reprojected && completeOnRay(ray, t, px * ray.dx + py * ray.dy + pz * ray.dz, length, reprojected, sr))) {
            double scale = radius / length;
            px *= scale;
            py *= scale;
            pz *= scale;
            sr.hitPoint.set(cx + px, cy + py, cz + pz);
            sr.hitError.set(g6 * (Math.abs(cx) + Math.abs(px)), g6 * (Math.abs(cy) + Math.abs(py)),
                            g6 * (Math.abs(cz) + Math.abs(pz)));
        }
        sr.normal.set(nx, ny, nz);
        sr.geometricNormal.set(sr.normal);
        if (!sr.world.needsTextureCoordinates()) {
            sr.scratch.skipped[Skipped.TEXTURE_COORDINATES]++;
            sr.u = 0;
            sr.v = 0;
            return;
        }
        // spherical coordinates as in Suffern, section 29.3: u around the y axis, v from the south pole
        double phi = Math.atan2(sr.normal.x, sr.normal.z) + Math.PI;
        sr.u = phi / (2 * Math.PI);
        sr.v = 1 - Math.acos(Math.max(-1, Math.min(1, sr.normal.y))) / Math.PI;
    }

    /**
     * Sets the hit point o + t d, with t (also {@code sr.t}) refined by a Newton step, if its error
     * bound along the normal is below {@code reprojected}; pDotD is (o + t d - c).d, half the
     * residual's slope in t.
     */
    private boolean completeOnRay(Ray ray, double t, double pDotD, double length, double reprojected, ShadeRec sr) {
        double g = Compensated.residual(ray.ox, ray.oy, ray.oz, t, ray.dx, ray.dy, ray.dz, cx, cy, cz, radius);
        double refined = t - g / (2 * pDotD);
        double gRefined = Compensated.residual(ray.ox, ray.oy, ray.oz, refined, ray.dx, ray.dy, ray.dz, cx, cy, cz, radius);
        // near a tangent the slope vanishes and the step may leap: keep it only if it helped
        if (Math.abs(gRefined) < Math.abs(g)) {
            t = refined;
            g = gRefined;
        }
        // distance from the surface of the exact point o + t d: (|p|^2 - r^2) / (|p| + r)
        double off = (Math.abs(g) + Compensated.errorBound(g, length, radius)) / (length + radius);
        double x = ray.atX(t);
        double y = ray.atY(t);
        double z = ray.atZ(t);
        double g2 = Rounding.gamma(2);
        // the rounding of o + t d per axis, plus the distance off the surface along the normal
        double ex = g2 * (Math.abs(ray.ox) + Math.abs(t * ray.dx));
        double ey = g2 * (Math.abs(ray.oy) + Math.abs(t * ray.dy));
        double ez = g2 * (Math.abs(ray.oz) + Math.abs(t * ray.dz));
        double nx = Math.abs(x - cx) / length;
        double ny = Math.abs(y - cy) / length;
        double nz = Math.abs(z - cz) / length;
        if (!(nx * ex + ny * ey + nz * ez + off < reprojected)) {
            return false;
        }
        sr.t = t;
        sr.hitPoint.set(x, y, z);
        sr.hitError.set(ex + off * nx, ey + off * ny, ez + off * nz);
        return true;
    }

    /**
     * A shadow ray from a lit point leaves the sphere: its origin is outside (offset by the hit's
     * error bound, with c = |o - c|^2 - r^2 recomputed exactly when small, so c &gt; 0) and it heads
     * away (f . d &gt; 0), so both roots are negative; a grazing ray misses (its line's closest
     * approach is the origin itself, outside by more than the discriminant's rounding).
     */
    @Override
    public boolean cannotShadowItself() {
        return true;
    }

    @Override
    public boolean isClosed() {
        return true;
    }

    @Override
    public BBox boundingBox() {
        return new BBox(cx - radius, cy - radius, cz - radius, cx + radius, cy + radius, cz + radius);
    }
}

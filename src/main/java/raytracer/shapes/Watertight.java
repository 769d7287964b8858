package raytracer.shapes;

import raytracer.core.ShadeRec;
import raytracer.math.Ray;
import raytracer.math.Rounding;
import raytracer.math.ShearedRay;
import raytracer.math.Vector3D;

/**
 * Watertight ray/triangle intersection (Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2013). The vertices are moved into a frame where the ray runs along +z from
 * the origin; the three 2D edge functions are then computed from the same operands for both
 * triangles that share an edge, so a ray through an edge or vertex hits at least one of them.
 * Shared by the single {@link Triangle} and the mesh triangles.
 */
public final class Watertight {
    private Watertight() {
    }

    /**
     * Distance to the triangle (vertices at offsets {@code a}, {@code b}, {@code c} of the flat
     * xyz array {@code v}) if it lies in (deltaT, tMax), with the barycentrics of b and c written to
     * {@code sr.b1}, {@code sr.b2}; otherwise +infinity and {@code sr} untouched. deltaT bounds the
     * rounding of t ({@link #tError}): a ray that starts on the triangle's plane (a hit on a flat
     * mesh at y = 0, whose error bound along y is 0, so its ray is not offset) computes a t of
     * either sign from the other coordinates' rounding, and without the bound would hit the floor it
     * leaves (pbrt-v3, section 3.9.6). An edge-on or degenerate triangle (det = 0) gets an infinite
     * or NaN t, which fails the range test.
     */
    public static double intersect(ShearedRay ray, double[] v, int a, int b, int c, double tMax, ShadeRec sr) {
        // JIT notes (README, "Speed"): no branch here may be rarely taken, since the JIT compiles
        // such a branch as a trap and taking it discards the compiled code; and the method stays
        // above the inlining limit, since inlined into the traversal it traced no faster and took
        // four times as long to compile, during the first render.
        int kx = ray.kx();
        int ky = ray.ky();
        int kz = ray.kz();
        double ox = ray.originX();
        double oy = ray.originY();
        double oz = ray.originZ();
        double sx = ray.sx();
        double sy = ray.sy();
        // vertices relative to the ray origin in the (kx, ky, kz) axis order, sheared so that the
        // ray direction becomes (0, 0, 1)
        double az = v[a + kz] - oz;
        double bz = v[b + kz] - oz;
        double cz = v[c + kz] - oz;
        double ax = v[a + kx] - ox - sx * az;
        double ay = v[a + ky] - oy - sy * az;
        double bx = v[b + kx] - ox - sx * bz;
        double by = v[b + ky] - oy - sy * bz;
        double cx = v[c + kx] - ox - sx * cz;
        double cy = v[c + ky] - oy - sy * cz;
        // scaled barycentrics: 2D edge functions
        double u = cx * by - cy * bx;
        double w1 = ax * cy - ay * cx;
        double w2 = bx * ay - by * ax;
        // outside when the edge functions have both signs (a zero counts as either); plain
        // comparisons joined without short-circuits, since Math.min and Math.max on doubles cost a
        // blend sequence each for NaN and -0.0 rules that this test does not need
        boolean someNegative = u < 0 | w1 < 0 | w2 < 0;
        boolean somePositive = u > 0 | w1 > 0 | w2 > 0;
        if (someNegative & somePositive) {
            return Double.POSITIVE_INFINITY;
        }
        double sz = ray.sz();
        double det = u + w1 + w2;
        // the corners' depths along the ray: t, their average weighted by the edge functions, lies among them
        double za = sz * az;
        double zb = sz * bz;
        double zc = sz * cz;
        double t = (u * za + w1 * zb + w2 * zc) / det;
        // 0 < t < tMax as one test (a NaN fails it): with gradual underflow tMax - t > 0 exactly when t < tMax
        if (!(t > 0 & tMax - t > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        // a triangle wholly ahead (every corner's depth positive, a sign rounding keeps) is met at
        // t > 0 in exact arithmetic too; one that reaches back to the origin is met only beyond
        // the rounding of t: the ray may have started on it
        if (!(za > 0 & zb > 0 & zc > 0) && !(t > tError(ax, ay, az, bx, by, bz, cx, cy, cz, u, w1, w2, sz, det, t, 0))) {
            return Double.POSITIVE_INFINITY;
        }
        sr.b1 = w1 / det;
        sr.b2 = w2 / det;
        return t;
    }

    /**
     * True when the ray certainly crosses the triangle strictly between its ends: at a t whose
     * distance from both 0 and {@code tMax} exceeds its error bound, the rounding of the test
     * itself ({@link #tError}) plus what the ray's own errors move it ({@link Ray#originError},
     * {@link Ray#directionError}, and the shear's rounding of the direction). A shadow ray aimed at
     * a light's point ends there: a triangle through that point, at any angle, touches the
     * light's end of the ray and does not block it.
     */
    public static boolean crossesWithin(ShearedRay ray, double[] v, int a, int b, int c, double tMax) {
        int kx = ray.kx();
        int ky = ray.ky();
        int kz = ray.kz();
        double ox = ray.originX();
        double oy = ray.originY();
        double oz = ray.originZ();
        double sx = ray.sx();
        double sy = ray.sy();
        double az = v[a + kz] - oz;
        double bz = v[b + kz] - oz;
        double cz = v[c + kz] - oz;
        double ax = v[a + kx] - ox - sx * az;
        double ay = v[a + ky] - oy - sy * az;
        double bx = v[b + kx] - ox - sx * bz;
        double by = v[b + ky] - oy - sy * bz;
        double cx = v[c + kx] - ox - sx * cz;
        double cy = v[c + ky] - oy - sy * cz;
        double u = cx * by - cy * bx;
        double w1 = ax * cy - ay * cx;
        double w2 = bx * ay - by * ax;
        boolean someNegative = u < 0 | w1 < 0 | w2 < 0;
        boolean somePositive = u > 0 | w1 > 0 | w2 > 0;
        if (someNegative & somePositive) {
            return false;
        }
        double sz = ray.sz();
        double det = u + w1 + w2;
        double za = sz * az;
        double zb = sz * bz;
        double zc = sz * cz;
        double t = (u * za + w1 * zb + w2 * zc) / det;
        if (!(t > 0 & tMax - t > 0)) {
            return false;
        }
        // Where the exact ray meets the triangle, its t is that point's depth (p_kz - o_kz) / d_kz,
        // within the corners' depths as the exact ray sees them: each computed one off by gamma(2)
        // of itself, plus originError |sz| from the origin, and divided by 1 -+ directionError |sz|
        // for the direction. A triangle whose corners all lie certainly between the ends (an
        // occluder in the middle of the ray: the usual case) blocks without the finer bound below.
        double g2 = Rounding.gamma(2);
        double absSz = Math.abs(sz);
        double shift = ray.originError() * absSz;
        double stretch = ray.directionError() * absSz;
        double nearest = Math.min(za, Math.min(zb, zc));
        double farthest = Math.max(za, Math.max(zb, zc));
        if (stretch < 1 && (nearest - g2 * Math.abs(nearest) - shift) / (1 + stretch) > 0
            && (farthest + g2 * Math.abs(farthest) + shift) / (1 - stretch) < tMax) {
            return true;
        }
        // the ray moved by a vector of at most e per axis moves the crossing by at most
        // e (|sz| + 2 (|N'x| + |N'y|) / |N'z|), N' the normal in the sheared frame (|sx|, |sy| <= 1)
        double nx = sz * ((by - ay) * (cz - az) - (bz - az) * (cy - ay));
        double ny = sz * ((bz - az) * (cx - ax) - (bx - ax) * (cz - az));
        double perUnit = Math.abs(sz) + 2 * (Math.abs(nx) + Math.abs(ny)) / Math.abs(det);
        // the shear stands for a direction off d by about 2u |d_kz| = 2u / |sz| per axis
        double directionError = ray.directionError() + Rounding.gamma(2) / Math.abs(sz);
        double margin = tError(ax, ay, az, bx, by, bz, cx, cy, cz, u, w1, w2, sz, det, t, Double.POSITIVE_INFINITY)
                        + (ray.originError() + t * directionError) * perUnit;
        return t - margin > 0 && tMax - t - margin > 0;
    }

    /**
     * A bound on the rounding of the t computed by the watertight test, from the same operands
     * (after pbrt-v3, section 3.9.6, with sums of magnitudes in place of maxima and the
     * denominator's error included): X, Y, Z bound the sheared coordinates, deltaX, deltaY,
     * deltaZ their rounding, deltaE that of each edge function; then the numerator
     * sum e_i sz z_i and the determinant sum e_i carry deltaN and deltaDet, and t = N / det is off
     * by (deltaN + |t| deltaDet) / (|det| - deltaDet) plus its own rounding. {@code uncertain}
     * when the determinant's sign is not certain, the ray running in the triangle's plane to
     * rounding: there no bound holds, and the closest hit keeps the paper's test (0: a grazing ray
     * still hits the face it comes from, and meets a mesh's triangles as watertight as before)
     * while a shadow ray is not blocked (+infinity).
     */
    private static double tError(double ax, double ay, double az, double bx, double by, double bz, double cx,
                                 double cy, double cz, double u, double w1, double w2, double sz, double det, double t,
                                 double uncertain) {
        double x = Math.abs(ax) + Math.abs(bx) + Math.abs(cx);
        double y = Math.abs(ay) + Math.abs(by) + Math.abs(cy);
        double z = Math.abs(az) + Math.abs(bz) + Math.abs(cz);
        double zScaled = Math.abs(sz) * z;
        double deltaZ = Rounding.gamma(3) * zScaled;
        double deltaX = Rounding.gamma(5) * (x + z);
        double deltaY = Rounding.gamma(5) * (y + z);
        double e = Math.abs(u) + Math.abs(w1) + Math.abs(w2);
        double deltaE = Rounding.gamma(2) * x * y + deltaX * y + deltaY * x;
        double deltaN = deltaE * zScaled + e * deltaZ + Rounding.gamma(3) * e * zScaled;
        double deltaDet = 3 * deltaE + Rounding.gamma(2) * e;
        double denominator = Math.abs(det) - deltaDet;
        double absT = Math.abs(t);
        return denominator > 0 ? (deltaN + absT * deltaDet) / denominator + Rounding.gamma(1) * absT : uncertain;
    }

    /**
     * Writes the hit point b0 a + b1 b + b2 c and its error bound gamma(7) sum |b_i p_i|
     * (pbrt-v3, section 3.9.4) into {@code sr}.
     */
    public static void interpolate(double[] v, int a, int b, int c, double b0, double b1, double b2,
                                   ShadeRec sr) {
        double g = Rounding.gamma(7);
        double x0 = b0 * v[a];
        double x1 = b1 * v[b];
        double x2 = b2 * v[c];
        double y0 = b0 * v[a + 1];
        double y1 = b1 * v[b + 1];
        double y2 = b2 * v[c + 1];
        double z0 = b0 * v[a + 2];
        double z1 = b1 * v[b + 2];
        double z2 = b2 * v[c + 2];
        sr.hitPoint.set(x0 + x1 + x2, y0 + y1 + y2, z0 + z1 + z2);
        sr.hitError.set(g * (Math.abs(x0) + Math.abs(x1) + Math.abs(x2)),
                        g * (Math.abs(y0) + Math.abs(y1) + Math.abs(y2)),
                        g * (Math.abs(z0) + Math.abs(z1) + Math.abs(z2)));
    }

    /**
     * True when the edges e1, e2 are (nearly) parallel: |e1 x e2| is within rounding of zero relative
     * to |e1| |e2|. Such a triangle has no area and never reports a hit.
     */
    public static boolean isDegenerate(Vector3D e1, Vector3D e2, Vector3D cross) {
        double area = cross.length();
        return !(area > Rounding.gamma(4) * e1.length() * e2.length()) || !Double.isFinite(area);
    }
}

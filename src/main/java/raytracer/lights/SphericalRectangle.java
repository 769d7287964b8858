package raytracer.lights;

import raytracer.math.MutableVec3;

/**
 * Uniform sampling of the solid angle a rectangle subtends (Urena, Fajardo and King, "An
 * Area-Preserving Parametrization for Spherical Rectangles", EGSR 2013, algorithm 1; pbrt-v4's
 * SampleSphericalRectangle), in the rectangle's own frame: the reference point at the origin, the
 * rectangle [x0, x1] x [y0, y1] in the plane z = z0 &lt; 0. The map of [0,1)^2 onto the rectangle is
 * continuous and preserves solid angle, so the strata of the pixel's sample values stay strata of
 * directions.
 *
 * <p>In double, and rewritten where the paper's formulas cancel: the edge planes' normals are
 * exact (each edge vector is an axis), the corner angles are taken in pairs as one atan2 each
 * ({@link #edgeAngle}), and the steps of the map avoid differences of nearly equal terms (see
 * below). Measured against the exact solid angles of sub-rectangles over random rectangles at
 * every scale and angle (six seeds of 400,000 rectangles), the map is then right to 1.2e-7 of u
 * for solid angles from 1e-5 to 2 pi (to 1e-11 of v; the worst at grazing angles near the
 * extension of an edge), and its error grows as the solid angle falls below that, which is where
 * the light samples by area ({@link #MIN_SOLID_ANGLE}).
 */
final class SphericalRectangle {
    /**
     * Below this solid angle the map's rounding, a few 1e-16 of the corner angles ({@link ArcTangent}
     * is within 4 ulps), is no longer well below 1e-7 of the solid angle (rectangles seen at grazing
     * angles far off to the side, whose corner angles stay large while the solid angle vanishes): there
     * the light samples by area.
     */
    static final double MIN_SOLID_ANGLE = 1e-5;

    private SphericalRectangle() {
    }

    /**
     * K(x) = g2 + g3 - pi for the rectangle whose edge at x0 lies at x: the sum of its corner
     * angles there, from the edge planes' normals n0 = (0, z0, -y0), n2 = (0, -z0, y1) and
     * n3 = (z0, 0, -x) (over their lengths). The solid angle of [xa, xb] x [y0, y1] is
     * K(xa) - K(xb) (Girard: the corner angles' sum less 2 pi; the other edge's pair,
     * g0 + g1 - pi, is -K(x1)). K is the argument of -e^{i g2} e^{i g3}, with
     * (cos g2, sin g2) = (x y1, |z0| l1) and (cos g3, sin g3) = (-x y0, |z0| l0) over positive
     * lengths that atan2 ignores, l_j = |(x, y_j, z0)|; no angle is close to wrapping, since the
     * sine's sign comes out exactly.
     */
    static double edgeAngle(double x, double y0, double y1, double z0) {
        double z2 = z0 * z0;
        double xz = x * x + z2;
        double l0 = Math.sqrt(xz + y0 * y0);
        double l1 = Math.sqrt(xz + y1 * y1);
        double sine = -z0 * x;
        double cosine = z2 * l0 * l1 + x * x * y0 * y1;
        if (y0 * y1 > 0) {
            // y0 l1 - y1 l0 cancels for y0, y1 of one sign: it is (y0^2 - y1^2)(x^2 + z0^2) / (y0 l1 + y1 l0),
            // and atan2 takes both arguments times |y0 l1 + y1 l0| as well
            double m = y0 * l1 + y1 * l0;
            return ArcTangent.atan2(sine * (y0 - y1) * (y0 + y1) * xz * Math.signum(m), cosine * Math.abs(m));
        }
        return ArcTangent.atan2(sine * (y0 * l1 - y1 * l0), cosine);
    }

    /** The solid angle of the rectangle, K(x0) - K(x1) ({@link #edgeAngle}); 0 unless z0 &lt; 0. */
    static double solidAngle(double x0, double y0, double x1, double y1, double z0) {
        if (!(z0 < 0)) {
            return 0;
        }
        return edgeAngle(x0, y0, y1, z0) - edgeAngle(x1, y0, y1, z0);
    }

    /**
     * Writes into {@code out.x}, {@code out.y} the point (xu, yv) of the rectangle for the sample
     * (u, v), given its solid angle S and k = {@link #edgeAngle}(x0) (S at least
     * {@link #MIN_SOLID_ANGLE}). The column x_u holds a share u of the solid angle: K(x_u) = k - u S.
     */
    static void sample(double x0, double y0, double x1, double y1, double z0, double solidAngle, double k, double u,
                       double v, MutableVec3 out) {
        double z2 = z0 * z0;
        double ly0 = Math.sqrt(y0 * y0 + z2);
        double ly1 = Math.sqrt(y1 * y1 + z2);
        // the paper's a_u = u S - g2 - g3 is phi - pi, phi = u S - k; its b0 = -y0 / ly0, b1 = y1 / ly1
        // and f_u = (cos(a_u) b0 - b1) / sin(a_u) = a / sin(phi) with a = b0 cos(phi) + b1. From the
        // half angle, sin(phi) = 2 s c, 1 - cos(phi) = 2 s^2, 1 + cos(phi) = 2 c^2, without division
        double phi = u * solidAngle - k;
        double s = Math.sin(0.5 * phi);
        double c = Math.cos(0.5 * phi);
        double sinPhi = 2 * s * c;
        // A = ly0 ly1 a = y1 ly0 - y0 ly1 cos(phi) in parts that do not cancel: (y1 ly0 - y0 ly1)
        // + y0 ly1 (1 - cos(phi)) where cos(phi) >= 0, else (y1 ly0 + y0 ly1) - y0 ly1 (1 + cos(phi));
        // y1 ly0 -+ y0 ly1, whose terms cancel for y0, y1 of one sign (-) or of opposite signs (+),
        // is then z0^2 (y1^2 - y0^2) / (y1 ly0 +- y0 ly1)
        double big;
        if (c * c >= s * s) {
            double difference = y0 * y1 > 0 ? z2 * (y1 - y0) * (y1 + y0) / (y1 * ly0 + y0 * ly1) : y1 * ly0 - y0 * ly1;
            big = difference + 2 * y0 * ly1 * s * s;
        } else {
            double sum = y0 * y1 < 0 ? z2 * (y1 - y0) * (y1 + y0) / (y1 * ly0 - y0 * ly1) : y1 * ly0 + y0 * ly1;
            big = sum - 2 * y0 * ly1 * c * c;
        }
        // c_u = sign(f_u) / sqrt(f_u^2 + b0^2) and x_u = -c_u z0 / sqrt(1 - c_u^2) become, with
        // 1 - b0^2 = (z0 / ly0)^2, x_u = -z0 sign(A) sin(phi) ly0 ly1 / sqrt(A^2 - (z0 ly1 sin(phi))^2)
        double zb = z0 * ly1 * sinPhi;
        double xu = -z0 * (big >= 0 ? sinPhi : -sinPhi) * ly0 * ly1 / Math.sqrt(big * big - zb * zb);
        if (!(xu >= x0)) { // also NaN, from a vanishing denominator at the edge
            xu = x0;
        } else if (xu > x1) {
            xu = x1;
        }
        // y_v: uniform in h = sin(elevation) = y / l, l = sqrt(d^2 + y^2), along the column at x_u;
        // near h = +-1 through m = 1 - |h| = d^2 / (l (l + |y|)), which keeps its precision there
        double d2 = xu * xu + z2;
        double l0 = Math.sqrt(d2 + y0 * y0);
        double l1 = Math.sqrt(d2 + y1 * y1);
        double m;
        boolean above;
        if (y0 >= 0) { // 1 - h falls from m0 to m1
            double m0 = d2 / (l0 * (l0 + y0));
            m = m0 - v * (m0 - d2 / (l1 * (l1 + y1)));
            above = true;
        } else if (y1 <= 0) { // 1 + h rises from m0 to m1
            double m0 = d2 / (l0 * (l0 - y0));
            m = m0 + v * (d2 / (l1 * (l1 - y1)) - m0);
            above = false;
        } else { // h0 < 0 < h1: h1 - h0 does not cancel; m from the nearer end
            double h0 = y0 / l0;
            double span = y1 / l1 - h0;
            above = h0 + v * span >= 0;
            m = above ? d2 / (l1 * (l1 + y1)) + (1 - v) * span : d2 / (l0 * (l0 - y0)) + v * span;
        }
        double yv = (1 - m) * Math.sqrt(d2 / (m * (2 - m)));
        if (!above) {
            yv = -yv;
        }
        if (!(yv >= y0)) {
            yv = y0;
        } else if (yv > y1) {
            yv = y1;
        }
        out.x = xu;
        out.y = yv;
    }
}

package raytracer.lights;

/**
 * atan2 in plain Java for the spherical rectangle's corner angles, two per light sample: this
 * JDK's Math.atan2 is a native call (fdlibm through JNI) that took a sixth of a render's time in a
 * profile of the area-light scene. The argument is reduced to |u| &lt;= tan(pi / 8) with
 * atan(t) = pi / 4 + atan((t - 1) / (t + 1)) and the octant's symmetries; there
 * atan(u) = u + u z P(z), z = u^2, P a polynomial of degree 10 fitted to (atan(sqrt z) / sqrt z - 1) / z
 * on [0, tan^2(pi / 8)] (mpmath 1.3.0, chebyfit, 50 digits), whose own error is below 3e-18 in the
 * angle; evaluated by Estrin's scheme, which halves the chain of dependent operations. Within a
 * few 1e-16 of Math.atan2 for finite arguments (ArcTangentTest).
 */
final class ArcTangent {
    private static final double TAN_PI_8 = 0.41421356237309503;
    private static final double PI_4 = Math.PI / 4;
    private static final double C0 = -0.3333333333333333;
    private static final double C1 = 0.1999999999999552;
    private static final double C2 = -0.14285714284666542;
    private static final double C3 = 0.11111111015256361;
    private static final double C4 = -0.09090904578123903;
    private static final double C5 = 0.07692183190826087;
    private static final double C6 = -0.06664511447381948;
    private static final double C7 = 0.0585814891280221;
    private static final double C8 = -0.0508544973794026;
    private static final double C9 = 0.03923165829558719;
    private static final double C10 = -0.01917688711906226;

    private ArcTangent() {
    }

    /** The angle of (x, y) in (-pi, pi], as Math.atan2(y, x); 0 for (0, 0). */
    static double atan2(double y, double x) {
        double ax = Math.abs(x);
        double ay = Math.abs(y);
        boolean steep = ay > ax;
        double small = steep ? ax : ay;
        double large = steep ? ay : ax;
        if (!(large > 0)) {
            return large == 0 ? Math.copySign(x < 0 || 1 / x < 0 ? Math.PI : 0, y) : Double.NaN;
        }
        // atan(small / large) in [0, pi / 4], from the reduced u with |u| <= tan(pi / 8)
        boolean upper = small > TAN_PI_8 * large;
        double u = upper ? (small - large) / (small + large) : small / large;
        double z = u * u;
        double z2 = z * z;
        double z4 = z2 * z2;
        double p = (C0 + C1 * z) + (C2 + C3 * z) * z2 + ((C4 + C5 * z) + (C6 + C7 * z) * z2) * z4
                   + ((C8 + C9 * z) + C10 * z2) * (z4 * z4);
        double a = u + u * z * p;
        if (upper) {
            a += PI_4;
        }
        if (steep) {
            a = Math.PI / 2 - a;
        }
        if (x < 0) {
            a = Math.PI - a;
        }
        return Math.copySign(a, y);
    }
}

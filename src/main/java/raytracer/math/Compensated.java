package raytracer.math;

/**
 * |o + t d - c|^2 - r^2 to about twice double precision, for a point near a sphere that is large
 * against the point's distance from it: there the plain formula loses every digit, since even
 * o - c is not a double (1 + 1e16 rounds to 1e16). Built from error-free transformations: Knuth's
 * TwoSum gives the rounding error of a sum, an FMA that of a product (Ogita, Rump and Oishi,
 * "Accurate sum and dot product", SIAM J. Sci. Comput. 26(6), 2005); the four large squares are
 * summed keeping their errors (their algorithm Sum2), the small terms are added last. The result is
 * within {@link #errorBound} of the exact value.
 */
public final class Compensated {
    private Compensated() {
    }

    /** The rounding error of {@code a + b}, given their rounded sum {@code s}: a + b = s + error exactly. */
    static double twoSumError(double a, double b, double s) {
        double bVirtual = s - a;
        return (a - (s - bVirtual)) + (b - bVirtual);
    }

    /**
     * |o + t d - c|^2 - r^2, each coordinate of o + t d - c carried as an exact sum of two doubles.
     * With t = 0 it is the constant term of the ray/sphere quadratic.
     */
    public static double residual(double ox, double oy, double oz, double t, double dx, double dy, double dz,
                                  double cx, double cy, double cz, double r) {
        // per axis: high part h = fl(fl(o - c) + fl(t d)), low part l with h + l = o - c + t d up to
        // u^2 |h|; then h^2 = p + e exactly (FMA), and (h + l)^2 = p + e + 2 h l + l^2
        double mx = t * dx;
        double my = t * dy;
        double mz = t * dz;
        double ax = ox - cx;
        double ay = oy - cy;
        double az = oz - cz;
        double hx = ax + mx;
        double hy = ay + my;
        double hz = az + mz;
        double lx = twoSumError(ox, -cx, ax) + Math.fma(t, dx, -mx) + twoSumError(ax, mx, hx);
        double ly = twoSumError(oy, -cy, ay) + Math.fma(t, dy, -my) + twoSumError(ay, my, hy);
        double lz = twoSumError(oz, -cz, az) + Math.fma(t, dz, -mz) + twoSumError(az, mz, hz);
        double px = hx * hx;
        double py = hy * hy;
        double pz = hz * hz;
        double pr = r * r;
        double small = Math.fma(hx, hx, -px) + Math.fma(hy, hy, -py) + Math.fma(hz, hz, -pz) - Math.fma(r, r, -pr)
                       + 2 * (hx * lx + hy * ly + hz * lz);
        double s1 = px + py;
        double s2 = s1 + pz;
        double s3 = s2 - pr;
        double errors = twoSumError(px, py, s1) + twoSumError(s1, pz, s2) + twoSumError(s2, -pr, s3);
        return s3 + (errors + small);
    }

    /**
     * A bound on |residual - exact| for a point at about distance {@code e} from the centre: u
     * |result| for the final rounding, and gamma(16)^2 (e^2 + r^2) for the rest. Sum2's bound is
     * gamma(n-1)^2 times the sum of the terms' magnitudes; with the rounding of the small terms
     * (each below 6u e^2) and the dropped l^2 (below 9u^2 e^2) the total stays under 100 u^2
     * (e^2 + r^2), and gamma(16)^2, about 256 u^2, leaves room.
     */
    public static double errorBound(double residual, double e, double r) {
        double g = Rounding.gamma(16);
        return 0x1.0p-53 * Math.abs(residual) + g * g * (e * e + r * r);
    }
}

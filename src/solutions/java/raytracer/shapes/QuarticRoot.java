package raytracer.shapes;

/**
 * The smallest root of a quartic c4 s^4 + c3 s^3 + c2 s^2 + c1 s + c0 in an interval, found without
 * the closed-form solution, whose cancellations lose most digits at a torus's scale: the roots of
 * the second derivative (a quadratic) cut the first derivative (a cubic) into monotone pieces,
 * whose roots, found by bisection, cut the quartic into monotone pieces; the first of those whose
 * ends differ in sign holds the root, found by bisection again. A root where the quartic only
 * touches zero (a ray grazing the surface) has no sign change and is not found.
 */
final class QuarticRoot {
    private QuarticRoot() {
    }

    /**
     * The smallest root in (lo, hi], or +infinity; with {@code closed}, a root exactly at lo counts
     * too (a ray whose search starts where it touches the torus).
     */
    static double smallest(double c4, double c3, double c2, double c1, double c0, double lo, double hi, boolean closed) {
        if (closed && c0 + lo * (c1 + lo * (c2 + lo * (c3 + lo * c4))) == 0) {
            return lo;
        }
        // the cubic q'(s) = 4 c4 s^3 + 3 c3 s^2 + 2 c2 s + c1 is monotone between the roots of q''
        double d3 = 4 * c4;
        double d2 = 3 * c3;
        double d1 = 2 * c2;
        double d0 = c1;
        double e2 = 3 * d3;
        double e1 = 2 * d2;
        double e0 = d1;
        double r1 = Double.NaN;
        double r2 = Double.NaN;
        double disc = e1 * e1 - 4 * e2 * e0;
        if (disc >= 0 && e2 != 0) {
            // the stable pair of quadratic roots (Numerical Recipes, section 5.6)
            double q = -0.5 * (e1 + Math.copySign(Math.sqrt(disc), e1));
            double a = q / e2;
            double b = q != 0 ? e0 / q : a;
            r1 = Math.min(a, b);
            r2 = Math.max(a, b);
        }
        // the quartic is monotone between the roots of the cubic, found in its monotone pieces
        double x = lo;
        double m1 = cubicRoot(d3, d2, d1, d0, lo, clamp(r1, lo, hi));
        double m2 = cubicRoot(d3, d2, d1, d0, clamp(r1, lo, hi), clamp(r2, lo, hi));
        double m3 = cubicRoot(d3, d2, d1, d0, clamp(r2, lo, hi), hi);
        for (int piece = 0; piece < 4; piece++) {
            double end = piece == 0 ? m1 : piece == 1 ? m2 : piece == 2 ? m3 : hi;
            if (!(end > x)) {
                continue; // no critical point there (NaN), or one at the same place
            }
            double root = quarticRoot(c4, c3, c2, c1, c0, x, end);
            if (root <= hi) {
                return root;
            }
            x = end;
        }
        return Double.POSITIVE_INFINITY;
    }

    private static double clamp(double v, double lo, double hi) {
        return Double.isNaN(v) ? lo : Math.max(lo, Math.min(hi, v));
    }

    /** The root of the cubic between lo and hi when its values there differ in sign, else NaN. */
    private static double cubicRoot(double d3, double d2, double d1, double d0, double lo, double hi) {
        double flo = ((d3 * lo + d2) * lo + d1) * lo + d0;
        double fhi = ((d3 * hi + d2) * hi + d1) * hi + d0;
        if (!(hi > lo) || (flo < 0) == (fhi < 0)) {
            return Double.NaN;
        }
        while (true) { // until lo and hi are neighbouring doubles
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            double f = ((d3 * mid + d2) * mid + d1) * mid + d0;
            if ((f < 0) == (flo < 0)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    }

    /** The root of the quartic in (lo, hi] when it is monotone there and changes sign, else +infinity. */
    private static double quarticRoot(double c4, double c3, double c2, double c1, double c0, double lo, double hi) {
        double flo = (((c4 * lo + c3) * lo + c2) * lo + c1) * lo + c0;
        double fhi = (((c4 * hi + c3) * hi + c2) * hi + c1) * hi + c0;
        if (flo == 0 || (fhi != 0 && (flo < 0) == (fhi < 0))) {
            return Double.POSITIVE_INFINITY;
        }
        while (true) { // until lo and hi are neighbouring doubles
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            double f = (((c4 * mid + c3) * mid + c2) * mid + c1) * mid + c0;
            if ((f < 0) == (flo < 0)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return hi;
    }
}

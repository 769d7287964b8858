package raytracer.io.obj;

/**
 * Decimal numbers parsed straight from a matched span of the line, without a substring. The fast
 * path is exact: a mantissa below 2^53 times a power of ten up to 10^22 is one correctly rounded
 * operation (Clinger, "How to read floating point numbers accurately", 1990); anything longer falls
 * back to {@link Double#parseDouble}.
 */
final class Numbers {
    private static final double[] POWERS = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    private Numbers() {
    }

    static double parseDouble(CharSequence s, int start, int end) {
        int i = start;
        boolean negative = false;
        char c = s.charAt(i);
        if (c == '-' || c == '+') {
            negative = c == '-';
            i++;
        }
        long mantissa = 0;
        int digits = 0;
        int scale = 0;
        boolean point = false;
        for (; i < end; i++) {
            c = s.charAt(i);
            if (c >= '0' && c <= '9') {
                if (mantissa == 0 && c == '0' && !point) {
                    continue; // leading zeros add nothing
                }
                mantissa = 10 * mantissa + (c - '0');
                digits++;
                if (point) {
                    scale--;
                }
            } else if (c == '.' && !point) {
                point = true;
            } else {
                break;
            }
        }
        if (i < end) {
            // saturated, so that an absurd exponent reaches Double.parseDouble (infinity or 0), not an overflow
            scale += Math.max(-100_000, Math.min(100_000, parseInt(s, i + 1, end)));
        }
        if (digits > 18 || mantissa >= (1L << 53) || scale < -22 || scale > 22) {
            return Double.parseDouble(s.subSequence(start, end).toString());
        }
        double v = scale >= 0 ? mantissa * POWERS[scale] : mantissa / POWERS[-scale];
        return negative ? -v : v;
    }

    static int parseInt(CharSequence s, int start, int end) {
        int i = start;
        boolean negative = s.charAt(i) == '-';
        if (negative || s.charAt(i) == '+') {
            i++;
        }
        long v = 0;
        for (; i < end; i++) {
            v = 10 * v + (s.charAt(i) - '0');
            if (v > Integer.MAX_VALUE) {
                return negative ? Integer.MIN_VALUE : Integer.MAX_VALUE;
            }
        }
        return (int) (negative ? -v : v);
    }
}

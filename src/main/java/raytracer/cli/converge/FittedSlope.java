package raytracer.cli.converge;

import java.util.Locale;

/**
 * A least-squares slope of log10(error) against log10(seconds), with its standard error
 * sqrt(s^2 / Sxx), s^2 the residuals' sum of squares over n - 2 (any regression text, e.g.
 * Montgomery and Runger, "Applied Statistics and Probability for Engineers", section 11.4). Two
 * points fit any line exactly and leave no residual to judge it by, so their slope is not given;
 * with three or four points the uncertainty is itself rough.
 */
record FittedSlope(double slope, double standardError, int points) {

    /** Fits {@code points} (x[i], y[i]), both positive, on log-log axes; NaN for fewer than two distinct x. */
    static FittedSlope of(double[] x, double[] y) {
        int n = x.length;
        double mx = 0;
        double my = 0;
        for (int i = 0; i < n; i++) {
            mx += Math.log10(x[i]) / n;
            my += Math.log10(y[i]) / n;
        }
        double sxy = 0;
        double sxx = 0;
        for (int i = 0; i < n; i++) {
            double dx = Math.log10(x[i]) - mx;
            sxy += dx * (Math.log10(y[i]) - my);
            sxx += dx * dx;
        }
        double slope = sxx > 0 ? sxy / sxx : Double.NaN;
        double residuals = 0;
        for (int i = 0; i < n; i++) {
            double r = Math.log10(y[i]) - my - slope * (Math.log10(x[i]) - mx);
            residuals += r * r;
        }
        double standardError = n > 2 && sxx > 0 ? Math.sqrt(residuals / (n - 2) / sxx) : Double.NaN;
        return new FittedSlope(slope, standardError, n);
    }

    /** "-0.49 +/- 0.03 (standard error, 6 points)", with a word of caution below five points. */
    String describe() {
        if (Double.isNaN(standardError)) {
            return "not fitted: " + points + " points leave nothing to judge a slope by (give five or more sample counts)";
        }
        return String.format(Locale.ROOT, "%.2f +/- %.2f (standard error, %d points%s)", slope, standardError, points,
                             points < 5 ? "; below five points the error itself is rough" : "");
    }
}

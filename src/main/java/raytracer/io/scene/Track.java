package raytracer.io.scene;

/**
 * One animated value (a point, a vector, an angle: {@code width} numbers) given at keyframes and
 * interpolated between them: linearly, or smoothly by the cubic Hermite curve through the keys
 * whose tangent at an inner key is the slope between its neighbours (Catmull-Rom on uneven key
 * spacing) and 0 at the first and last key, so a move eases in and out and its speed has no jump
 * at an inner key. Before the first key the value is the first key's, after the last the last's.
 */
final class Track {
    private final double[] times;
    private final double[][] values;
    private final boolean smooth;

    /** {@code times} strictly increasing (frames), one row of {@code values} per key. */
    Track(double[] times, double[][] values, boolean smooth) {
        if (times.length == 0 || times.length != values.length) {
            throw new IllegalArgumentException("a track needs one value per key, and at least one key");
        }
        for (int k = 1; k < times.length; k++) {
            if (!(times[k] > times[k - 1])) {
                throw new IllegalArgumentException("key times must increase");
            }
        }
        this.times = times.clone();
        this.values = values.clone();
        this.smooth = smooth;
    }

    /** The value at frame {@code t} (fractional frames allowed). */
    double[] at(double t) {
        int n = times.length;
        if (t <= times[0]) {
            return values[0].clone();
        }
        if (t >= times[n - 1]) {
            return values[n - 1].clone();
        }
        int k = 0;
        while (t >= times[k + 1]) {
            k++;
        }
        double h = times[k + 1] - times[k];
        double s = (t - times[k]) / h;
        double[] p0 = values[k];
        double[] p1 = values[k + 1];
        double[] out = new double[p0.length];
        if (!smooth) {
            for (int i = 0; i < out.length; i++) {
                out[i] = p0[i] + s * (p1[i] - p0[i]);
            }
            return out;
        }
        // cubic Hermite basis (e.g. pbrt-v4's and every animation package's): p(s) = h00 p0 + h10 h m0 + h01 p1 + h11 h m1
        double s2 = s * s;
        double s3 = s2 * s;
        double h00 = 2 * s3 - 3 * s2 + 1;
        double h10 = s3 - 2 * s2 + s;
        double h01 = -2 * s3 + 3 * s2;
        double h11 = s3 - s2;
        for (int i = 0; i < out.length; i++) {
            out[i] = h00 * p0[i] + h10 * h * tangent(k, i) + h01 * p1[i] + h11 * h * tangent(k + 1, i);
        }
        return out;
    }

    /** The slope of component {@code i} at key {@code k}: between its neighbours, 0 at either end. */
    private double tangent(int k, int i) {
        if (k == 0 || k == times.length - 1) {
            return 0;
        }
        return (values[k + 1][i] - values[k - 1][i]) / (times[k + 1] - times[k - 1]);
    }
}

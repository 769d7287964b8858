package raytracer.render;

/** What a render did: resolution, samples, threads, wall time and the rays it traced. */
public record RenderStats(int width, int height, int samplesPerPixel, int threads, long wallNanos,
                          long primaryRays, long secondaryRays, long shadowRays, long nonFiniteSamples,
                          long boxTests) {

    public long totalRays() {
        return primaryRays + secondaryRays + shadowRays;
    }

    public double seconds() {
        return wallNanos / 1e9;
    }

    /** Bounding-volume tests per traced ray (primary, secondary and shadow). */
    public double boxTestsPerRay() {
        return (double) boxTests / Math.max(1, totalRays());
    }

    public double raysPerSecond() {
        return totalRays() / Math.max(seconds(), 1e-9);
    }
}

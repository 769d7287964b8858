package raytracer.render;

import raytracer.core.Skipped;

/**
 * What a render did: resolution, samples, threads, wall time, the rays it traced, and the work the
 * scene analysis left out, one count per {@link Skipped} kind.
 */
public record RenderStats(int width, int height, int samplesPerPixel, int threads, long wallNanos,
                          long primaryRays, long secondaryRays, long shadowRays, long nonFiniteSamples,
                          long boxTests, long[] skipped) {

    /** A render that left nothing out. */
    public RenderStats(int width, int height, int samplesPerPixel, int threads, long wallNanos, long primaryRays,
                       long secondaryRays, long shadowRays, long nonFiniteSamples, long boxTests) {
        this(width, height, samplesPerPixel, threads, wallNanos, primaryRays, secondaryRays, shadowRays, nonFiniteSamples,
             boxTests, new long[Skipped.KINDS]);
    }

    public RenderStats {
        skipped = skipped.clone();
    }

    /** The counts per {@link Skipped} kind (a copy). */
    @Override
    public long[] skipped() {
        return skipped.clone();
    }

    /** How much work of {@code kind} ({@link Skipped}) the render left out. */
    public long skipped(int kind) {
        return skipped[kind];
    }

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

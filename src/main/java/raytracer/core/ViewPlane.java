package raytracer.core;

/**
 * Image settings (Suffern, section 3.4): resolution, samples per pixel and their pattern, the
 * deepest recursion, the exposure applied before display encoding, and the filter that makes
 * pixels from samples (the book's box unless a scene asks for another).
 */
public record ViewPlane(int hres, int vres, int numSamples, Sampler sampler, int maxDepth, double exposure,
                        PixelFilter filter) {
    /**
     * The deepest recursion allowed. Each level holds a hit record per worker (about 10 KB: 100000
     * levels ran out of memory) and three or four stack frames of the worker thread, whose default
     * stack held 1500 levels of glossy rays through an instance but not 2000 (cold JVM, 2025).
     */
    public static final int MAX_DEPTH = 1000;

    public ViewPlane {
        if (hres < 1 || vres < 1) {
            throw new IllegalArgumentException("image size must be at least 1x1, got " + hres + "x" + vres);
        }
        if (numSamples < 1 || numSamples > Sampler.MAX_SAMPLES) {
            throw new IllegalArgumentException("samples per pixel must be 1 to " + Sampler.MAX_SAMPLES + ", got " + numSamples);
        }
        if (maxDepth < 0 || maxDepth > MAX_DEPTH) {
            throw new IllegalArgumentException("max depth must be 0 to " + MAX_DEPTH + ", got " + maxDepth);
        }
        if (!(exposure > 0) || !Double.isFinite(exposure)) {
            throw new IllegalArgumentException("exposure must be a positive number, got " + exposure);
        }
        if (filter == null) {
            throw new IllegalArgumentException("a view plane needs a pixel filter");
        }
        numSamples = sampler.supportedCount(numSamples);
    }

    /** The book's view plane: each pixel the plain average of its own samples. */
    public ViewPlane(int hres, int vres, int numSamples, Sampler sampler, int maxDepth, double exposure) {
        this(hres, vres, numSamples, sampler, maxDepth, exposure, PixelFilter.BOX);
    }

    public ViewPlane withResolution(int h, int v) {
        return new ViewPlane(h, v, numSamples, sampler, maxDepth, exposure, filter);
    }

    public ViewPlane withSamples(int n) {
        return new ViewPlane(hres, vres, n, sampler, maxDepth, exposure, filter);
    }

    /** The same settings with another sample pattern; the sample count is rounded for it anew. */
    public ViewPlane withSampler(Sampler s) {
        return new ViewPlane(hres, vres, numSamples, s, maxDepth, exposure, filter);
    }

    public ViewPlane withMaxDepth(int d) {
        return new ViewPlane(hres, vres, numSamples, sampler, d, exposure, filter);
    }

    public ViewPlane withFilter(PixelFilter f) {
        return new ViewPlane(hres, vres, numSamples, sampler, maxDepth, exposure, f);
    }
}

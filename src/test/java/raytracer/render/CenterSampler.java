package raytracer.render;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/** One sample at the pixel centre, so tests know exactly which ray each pixel traced. */
enum CenterSampler implements Sampler {
    INSTANCE;

    @Override
    public int supportedCount(int requested) {
        return 1;
    }

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        xs[0] = 0.5;
        ys[0] = 0.5;
    }
}

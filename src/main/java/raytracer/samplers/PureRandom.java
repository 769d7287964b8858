package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/** Independent uniform points (Suffern, section 5.2.2): unbiased, but clumped. */
public final class PureRandom implements Sampler {

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        for (int i = 0; i < n; i++) {
            xs[i] = rng.nextDouble();
            ys[i] = rng.nextDouble();
        }
    }
}

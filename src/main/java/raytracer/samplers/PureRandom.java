package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Hashes;
import raytracer.math.Rng;

/**
 * Independent uniform points (Suffern, section 5.2.2): unbiased, but clumped. Pointwise: point i is
 * a hash of the scramble and i, so a sample's value does not depend on the other samples.
 */
public final class PureRandom implements Sampler {

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        for (int i = 0; i < n; i++) {
            xs[i] = rng.nextDouble();
            ys[i] = rng.nextDouble();
        }
    }

    @Override
    public boolean pointwise() {
        return true;
    }

    @Override
    public long point(int index, long scramble) {
        return Hashes.mix(scramble, index);
    }
}

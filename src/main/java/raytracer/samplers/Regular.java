package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/** Cell centres of a k x k grid (Suffern, section 5.2.1): no randomness, so aliasing stays visible. */
public final class Regular implements Sampler {

    @Override
    public int supportedCount(int requested) {
        return SquareCount.roundUp(requested);
    }

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        int k = SquareCount.side(n);
        for (int row = 0; row < k; row++) {
            for (int col = 0; col < k; col++) {
                xs[row * k + col] = (col + 0.5) / k;
                ys[row * k + col] = (row + 0.5) / k;
            }
        }
    }
}

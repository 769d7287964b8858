package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/** One uniform point in each cell of a k x k grid (Suffern, section 5.2.3). */
public final class Jittered implements Sampler {

    @Override
    public int supportedCount(int requested) {
        return SquareCount.roundUp(requested);
    }

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        int k = SquareCount.side(n);
        for (int row = 0; row < k; row++) {
            for (int col = 0; col < k; col++) {
                xs[row * k + col] = SquareCount.clamp((col + rng.nextDouble()) / k);
                ys[row * k + col] = SquareCount.clamp((row + rng.nextDouble()) / k);
            }
        }
    }
}

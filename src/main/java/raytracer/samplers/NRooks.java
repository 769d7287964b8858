package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/**
 * n-rooks sampling (Shirley 1991; Suffern, section 5.2.4): point i lies in row i of an n x n grid,
 * and the columns are a random permutation, so every row and every column holds one point.
 */
public final class NRooks implements Sampler {

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        for (int i = 0; i < n; i++) {
            xs[i] = SquareCount.clamp((i + rng.nextDouble()) / n);
            ys[i] = SquareCount.clamp((i + rng.nextDouble()) / n);
        }
        // Fisher-Yates shuffle of the x coordinates keeps one point per column
        for (int i = n - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            double t = xs[i];
            xs[i] = xs[j];
            xs[j] = t;
        }
    }
}

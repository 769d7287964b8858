package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/**
 * Correlated multi-jittered sampling (Kensler, "Correlated Multi-Jittered Sampling", Pixar
 * technical memo 13-01, 2013): multi-jittered points, n = k * k, one in each cell of the k x k grid
 * and one in each row and column of the n x n subgrid, where {@link MultiJittered} shuffles the
 * subcolumns of each cell column on its own, here one shuffle serves every cell column, and one
 * every cell row. The points of a row of cells then sit at the same offset within their cells, one
 * cell apart, and likewise down a column, so they clump less: where an edge crosses the pixel the
 * error is lower (Kensler's figures), while a smooth integrand that varies in x and y together is
 * averaged worse (docs/converge.md, "Correlated multi-jittered", for this renderer's figures).
 */
public final class CorrelatedMultiJittered implements Sampler {

    @Override
    public int supportedCount(int requested) {
        return SquareCount.roundUp(requested);
    }

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        int k = SquareCount.side(n);
        int[] sigma = permutation(k, rng);
        int[] tau = permutation(k, rng);
        // the point of cell column i and cell row j: subcolumn i k + sigma(j), subrow j k + tau(i);
        // sigma(j) over the rows of one column is a permutation, so the subcolumns are all used once
        for (int j = 0; j < k; j++) {
            for (int i = 0; i < k; i++) {
                xs[j * k + i] = SquareCount.clamp((i * k + sigma[j] + rng.nextDouble()) / n);
                ys[j * k + i] = SquareCount.clamp((j * k + tau[i] + rng.nextDouble()) / n);
            }
        }
    }

    /** A uniformly random permutation of 0 .. k - 1 (Fisher and Yates). */
    private static int[] permutation(int k, Rng rng) {
        int[] p = new int[k];
        for (int i = 0; i < k; i++) {
            p[i] = i;
        }
        for (int i = k - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            int t = p[i];
            p[i] = p[j];
            p[j] = t;
        }
        return p;
    }
}

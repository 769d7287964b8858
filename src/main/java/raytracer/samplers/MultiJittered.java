package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/**
 * Multi-jittered sampling (Chiu, Shirley and Wang 1994; Suffern, section 5.2.5): n = k * k points,
 * one in each cell of the k x k grid and, at the same time, one in each row and column of the
 * n x n subgrid. Starts from the canonical arrangement, then shuffles x within each column of cells
 * and y within each row of cells, which keeps both properties.
 */
public final class MultiJittered implements Sampler {

    @Override
    public int supportedCount(int requested) {
        return SquareCount.roundUp(requested);
    }

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        int k = SquareCount.side(n);
        // canonical arrangement: point (i, j) lies in cell column i and cell row j, in subcolumn
        // i k + j and subrow j k + i, so every cell, subcolumn and subrow is used exactly once
        for (int i = 0; i < k; i++) {
            for (int j = 0; j < k; j++) {
                xs[i * k + j] = (i * k + j + rng.nextDouble()) / n;
                ys[i * k + j] = (j * k + i + rng.nextDouble()) / n;
            }
        }
        // exchange x among the points of one cell column (fixed i): they keep their cells
        for (int i = 0; i < k; i++) {
            for (int j = 0; j < k; j++) {
                int other = i * k + j + rng.nextInt(k - j);
                double t = xs[i * k + j];
                xs[i * k + j] = xs[other];
                xs[other] = t;
            }
        }
        // and y among the points of one cell row (fixed j)
        for (int j = 0; j < k; j++) {
            for (int i = 0; i < k; i++) {
                int other = (i + rng.nextInt(k - i)) * k + j;
                double t = ys[i * k + j];
                ys[i * k + j] = ys[other];
                ys[other] = t;
            }
        }
        for (int i = 0; i < n; i++) {
            xs[i] = SquareCount.clamp(xs[i]);
            ys[i] = SquareCount.clamp(ys[i]);
        }
    }
}

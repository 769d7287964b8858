package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/**
 * The Hammersley point set (Suffern, section 5.2.6): x = i / n, y = the base-2 radical inverse of i.
 * Deterministic, so it ignores the generator and every pixel uses the same pattern.
 */
public final class Hammersley implements Sampler {

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        for (int i = 0; i < n; i++) {
            xs[i] = (double) i / n;
            ys[i] = radicalInverse(i);
        }
    }

    /** Mirrors the binary digits of i about the binary point: 1 -> 0.5, 2 -> 0.25, 3 -> 0.75. */
    static double radicalInverse(int i) {
        return (Integer.reverse(i) >>> 1) * 0x1.0p-31;
    }
}

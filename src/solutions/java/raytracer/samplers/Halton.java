package raytracer.samplers;

import raytracer.core.Sampler;
import raytracer.math.Rng;

/**
 * Reference solution of exercise 1 (docs/teaching.md): the Halton points (phi_2(i), phi_3(i)),
 * i = 0 .. n-1, phi_b the radical inverse in base b (Halton 1960; Suffern's Hammersley, section
 * 5.2.6, uses phi_2 the same way), shifted modulo 1 by an offset per axis drawn from the pixel's
 * generator (Cranley and Patterson 1976): each pixel's pattern differs, every point is uniform,
 * and the set keeps its low discrepancy.
 */
public final class Halton implements Sampler {

    @Override
    public void generate(int n, Rng rng, double[] xs, double[] ys) {
        double shiftX = rng.nextDouble();
        double shiftY = rng.nextDouble();
        for (int i = 0; i < n; i++) {
            xs[i] = wrap(Hammersley.radicalInverse(i) + shiftX);
            ys[i] = wrap(radicalInverse3(i) + shiftY);
        }
    }

    /** The base-3 digits of i mirrored about the point: 1 -> 1/3, 2 -> 2/3, 3 -> 1/9. */
    private static double radicalInverse3(int i) {
        double value = 0;
        double digitWeight = 1.0 / 3;
        for (int rest = i; rest > 0; rest /= 3) {
            value += (rest % 3) * digitWeight;
            digitWeight /= 3;
        }
        return value;
    }

    /** v mod 1 for v in [0, 2); a sum that rounds up to 1 becomes 0, keeping the point in [0, 1). */
    private static double wrap(double v) {
        return v >= 1 ? v - 1 : v;
    }
}

package raytracer.textures;

import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.Rng;

/**
 * Reference solution of exercise 8 (docs/teaching.md): a solid texture of gradient noise (Perlin,
 * "Improving noise", SIGGRAPH 2002). Each lattice point gets one of the twelve directions to the
 * edges of a cube, picked by hashing its coordinates through a permutation of 0..255; the noise is
 * the interpolation of each corner's gradient times the offset from that corner, with the weights
 * 6t^5 - 15t^4 + 10t^3, whose first and second derivatives vanish at the lattice planes. The colour
 * is low + (high - low) t, with t = (1 + n) / 2 clamped to [0, 1].
 */
public final class GradientNoise implements Texture {
    /** A fixed permutation, twice over so that hashes need no wrapping; the same for every instance. */
    private static final int[] PERMUTATION = permutation(2002);
    private final RGBColor low;
    private final RGBColor high;
    private final double scale;

    public GradientNoise(RGBColor low, RGBColor high, double scale) {
        if (!(scale > 0) || !Double.isFinite(scale)) {
            throw new IllegalArgumentException("noise scale must be a positive number, got " + scale);
        }
        this.low = low;
        this.high = high;
        this.scale = scale;
    }

    @Override
    public void getColor(ShadeRec sr, MutableRgb out) {
        double n = noise(sr.localHitPoint.x / scale, sr.localHitPoint.y / scale, sr.localHitPoint.z / scale);
        double t = Math.max(0, Math.min(1, (1 + n) / 2));
        out.set(low.r() + t * (high.r() - low.r()), low.g() + t * (high.g() - low.g()), low.b() + t * (high.b() - low.b()));
    }

    static double noise(double x, double y, double z) {
        double fx = Math.floor(x);
        double fy = Math.floor(y);
        double fz = Math.floor(z);
        int i = (int) fx & 255;
        int j = (int) fy & 255;
        int k = (int) fz & 255;
        x -= fx;
        y -= fy;
        z -= fz;
        double u = fade(x);
        double v = fade(y);
        double w = fade(z);
        int[] p = PERMUTATION;
        // the hashes of the cell's eight corners
        int a = p[i] + j;
        int aa = p[a] + k;
        int ab = p[a + 1] + k;
        int b = p[i + 1] + j;
        int ba = p[b] + k;
        int bb = p[b + 1] + k;
        double bottom = lerp(v, lerp(u, grad(p[aa], x, y, z), grad(p[ba], x - 1, y, z)),
                                lerp(u, grad(p[ab], x, y - 1, z), grad(p[bb], x - 1, y - 1, z)));
        double top = lerp(v, lerp(u, grad(p[aa + 1], x, y, z - 1), grad(p[ba + 1], x - 1, y, z - 1)),
                             lerp(u, grad(p[ab + 1], x, y - 1, z - 1), grad(p[bb + 1], x - 1, y - 1, z - 1)));
        return lerp(w, bottom, top);
    }

    private static double fade(double t) {
        return t * t * t * (t * (6 * t - 15) + 10);
    }

    private static double lerp(double t, double a, double b) {
        return a + t * (b - a);
    }

    /** The dot product of (x, y, z) with one of the twelve cube-edge directions, chosen by the hash. */
    private static double grad(int hash, double x, double y, double z) {
        return switch (hash % 12) {
            case 0 -> x + y;
            case 1 -> -x + y;
            case 2 -> x - y;
            case 3 -> -x - y;
            case 4 -> x + z;
            case 5 -> -x + z;
            case 6 -> x - z;
            case 7 -> -x - z;
            case 8 -> y + z;
            case 9 -> -y + z;
            case 10 -> y - z;
            default -> -y - z;
        };
    }

    /** A Fisher-Yates shuffle of 0..255 from a fixed seed, stored twice. */
    private static int[] permutation(long seed) {
        int[] p = new int[512];
        for (int i = 0; i < 256; i++) {
            p[i] = i;
        }
        Rng rng = new Rng(seed);
        for (int i = 255; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            int swap = p[i];
            p[i] = p[j];
            p[j] = swap;
        }
        System.arraycopy(p, 0, p, 256, 256);
        return p;
    }
}

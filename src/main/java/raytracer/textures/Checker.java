package raytracer.textures;

import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/** A checkerboard in texture space: squares of {@code size} in u and v alternate two colours. */
public final class Checker implements Texture {
    private final RGBColor a;
    private final RGBColor b;
    private final double size;

    public Checker(RGBColor a, RGBColor b, double size) {
        if (!(size > 0)) {
            throw new IllegalArgumentException("checker size must be positive, got " + size);
        }
        this.a = a;
        this.b = b;
        this.size = size;
    }

    @Override
    public void getColor(ShadeRec sr, MutableRgb out) {
        long i = (long) Math.floor(sr.u / size) + (long) Math.floor(sr.v / size);
        out.set((i & 1) == 0 ? a : b);
    }
}

package raytracer.filters;

import raytracer.core.PixelFilter;

/** Reference solution of exercise 9: the tent filter, w(d) = max(0, 1 - |d| / r) (pbrt-v3, section 7.8.1). */
public final class Tent implements PixelFilter {
    private final double radius;

    public Tent(double radius) {
        if (!(radius > 0.5 && radius <= 8)) {
            throw new IllegalArgumentException("the tent's radius must be above 0.5 and at most 8 pixels, got " + radius);
        }
        this.radius = radius;
    }

    @Override
    public String name() {
        return "tent";
    }

    @Override
    public double radius() {
        return radius;
    }

    @Override
    public double weight(double d) {
        return Math.max(0, 1 - Math.abs(d) / radius);
    }
}

package raytracer.core;

/** The box of half-width 0.5 pixel: weight 1 inside a pixel, 0 outside ({@link PixelFilter#BOX}). */
final class BoxFilter implements PixelFilter {
    @Override
    public String name() {
        return "box";
    }

    @Override
    public double radius() {
        return 0.5;
    }

    @Override
    public double weight(double d) {
        return Math.abs(d) < 0.5 ? 1 : 0;
    }

    @Override
    public boolean isBox() {
        return true;
    }

    @Override
    public String toString() {
        return name();
    }
}

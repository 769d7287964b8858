package raytracer.math;

/** An immutable linear RGB triple: a reflectance, a light colour or a radiance. */
public record RGBColor(double r, double g, double b) {

    public static final RGBColor BLACK = new RGBColor(0, 0, 0);
    public static final RGBColor WHITE = new RGBColor(1, 1, 1);

    public static RGBColor gray(double v) {
        return new RGBColor(v, v, v);
    }

    public RGBColor scale(double s) {
        return new RGBColor(r * s, g * s, b * s);
    }

    public RGBColor mul(RGBColor c) {
        return new RGBColor(r * c.r, g * c.g, b * c.b);
    }

    public RGBColor add(RGBColor c) {
        return new RGBColor(r + c.r, g + c.g, b + c.b);
    }

    public double max() {
        return Math.max(r, Math.max(g, b));
    }

    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }
}

package raytracer.math;

/** A mutable RGB accumulator: radiance is summed into one of these instead of allocating colours. */
public final class MutableRgb {
    public double r;
    public double g;
    public double b;

    public MutableRgb set(double r, double g, double b) {
        this.r = r;
        this.g = g;
        this.b = b;
        return this;
    }

    public MutableRgb set(RGBColor c) {
        return set(c.r(), c.g(), c.b());
    }

    public MutableRgb set(MutableRgb c) {
        return set(c.r, c.g, c.b);
    }

    public MutableRgb setBlack() {
        return set(0, 0, 0);
    }

    public MutableRgb add(MutableRgb c) {
        r += c.r;
        g += c.g;
        b += c.b;
        return this;
    }

    /** this += c * s, the step of every sum over lights and samples. */
    public MutableRgb addScaled(RGBColor c, double s) {
        r += c.r() * s;
        g += c.g() * s;
        b += c.b() * s;
        return this;
    }

    /** this += p * c * s, component-wise. */
    public MutableRgb addProduct(MutableRgb p, RGBColor c, double s) {
        r += p.r * c.r() * s;
        g += p.g * c.g() * s;
        b += p.b * c.b() * s;
        return this;
    }

    /** this += p * q * s, component-wise. */
    public MutableRgb addProduct(MutableRgb p, MutableRgb q, double s) {
        r += p.r * q.r * s;
        g += p.g * q.g * s;
        b += p.b * q.b * s;
        return this;
    }

    public MutableRgb scale(double s) {
        r *= s;
        g *= s;
        b *= s;
        return this;
    }

    public MutableRgb mul(RGBColor c) {
        r *= c.r();
        g *= c.g();
        b *= c.b();
        return this;
    }

    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }

    public RGBColor toColor() {
        return new RGBColor(r, g, b);
    }

    @Override
    public String toString() {
        return "(" + r + ", " + g + ", " + b + ")";
    }
}

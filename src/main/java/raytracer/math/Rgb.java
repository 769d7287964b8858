package raytracer.math;

/** A mutable RGB accumulator: radiance is summed into one of these instead of allocating colours. */
public final class Rgb {
    public double r;
    public double g;
    public double b;

    public Rgb set(double r, double g, double b) {
        this.r = r;
        this.g = g;
        this.b = b;
        return this;
    }

    public Rgb set(RGBColor c) {
        return set(c.r(), c.g(), c.b());
    }

    public Rgb set(Rgb c) {
        return set(c.r, c.g, c.b);
    }

    public Rgb setBlack() {
        return set(0, 0, 0);
    }

    public Rgb add(Rgb c) {
        r += c.r;
        g += c.g;
        b += c.b;
        return this;
    }

    /** this += c * s, the step of every sum over lights and samples. */
    public Rgb addScaled(RGBColor c, double s) {
        r += c.r() * s;
        g += c.g() * s;
        b += c.b() * s;
        return this;
    }

    /** this += p * c * s, component-wise. */
    public Rgb addProduct(Rgb p, RGBColor c, double s) {
        r += p.r * c.r() * s;
        g += p.g * c.g() * s;
        b += p.b * c.b() * s;
        return this;
    }

    /** this += p * q * s, component-wise. */
    public Rgb addProduct(Rgb p, Rgb q, double s) {
        r += p.r * q.r * s;
        g += p.g * q.g * s;
        b += p.b * q.b * s;
        return this;
    }

    public Rgb scale(double s) {
        r *= s;
        g *= s;
        b *= s;
        return this;
    }

    public Rgb mul(RGBColor c) {
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

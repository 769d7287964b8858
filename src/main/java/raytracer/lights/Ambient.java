package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/** Constant light from everywhere, L = ls c (Suffern, section 14.3); it has no direction. */
public final class Ambient extends Light {
    private final RGBColor radiance;

    public Ambient(double ls, RGBColor color) {
        this.radiance = color.scale(ls);
        setCastsShadows(false);
    }

    @Override
    public double getDirection(ShadeRec sr, MutableVec3 wi) {
        wi.set(0, 0, 0);
        return 0;
    }

    @Override
    public boolean isBlack() {
        return radiance.isBlack();
    }

    @Override
    public void L(ShadeRec sr, MutableRgb out) {
        out.set(radiance);
    }

    /** L = ls c. */
    public RGBColor radiance() {
        return radiance;
    }
}

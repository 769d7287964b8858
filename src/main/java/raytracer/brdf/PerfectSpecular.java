package raytracer.brdf;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * A perfect mirror (Suffern, section 24.2): all reflected light leaves along the mirror direction
 * r = -wo + 2 (n . wo) n, scaled by kr cr. Its f is a delta, f = kr cr delta(wi - r) / cos(theta_i),
 * so it is sampled, never evaluated: {@link #f} and {@link #pdf} are zero for every direction, and
 * {@link #sampleF} returns r with the weight f cos / pdf = kr cr.
 */
public final class PerfectSpecular implements BRDF {
    private final RGBColor reflectance;

    public PerfectSpecular(double kr, RGBColor cr) {
        this.reflectance = cr.scale(kr);
    }

    /** True when kr cr is black: every mirror ray would be weighted 0. */
    @Override
    public boolean isBlack() {
        return reflectance.isBlack();
    }

    /** Zero: no finite direction-to-direction value exists for a delta. */
    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        out.setBlack();
    }

    /** Writes the mirror direction of {@code wo} about the shading normal into {@code wi}, weight kr cr; (u, v) is unused. */
    @Override
    public boolean sampleF(ShadeRec sr, MutableVec3 wo, double u, double v, MutableVec3 wi, MutableRgb weight) {
        MutableVec3 n = sr.normal;
        double nDotWo = n.dot(wo);
        wi.set(-wo.x + 2 * nDotWo * n.x, -wo.y + 2 * nDotWo * n.y, -wo.z + 2 * nDotWo * n.z);
        weight.set(reflectance);
        return true;
    }

    /** Zero: the chance of picking any given direction other than by {@link #sampleF} is nil. */
    @Override
    public double pdf(ShadeRec sr, MutableVec3 wo, MutableVec3 wi) {
        return 0;
    }

    /** Zero, as in the book: ambient light is not mirrored. */
    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        out.setBlack();
    }

    /** kr cr, the weight of the mirror direction. */
    public RGBColor reflectance() {
        return reflectance;
    }
}

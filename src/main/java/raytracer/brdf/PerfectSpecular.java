package raytracer.brdf;

import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Vec3;

/**
 * A perfect mirror (Suffern, section 24.2): all reflected light leaves along r = -wo + 2 (n . wo) n,
 * scaled by kr cr. It is a delta distribution, so it is sampled, never evaluated.
 */
public final class PerfectSpecular {
    private final double kr;
    private final RGBColor cr;

    public PerfectSpecular(double kr, RGBColor cr) {
        this.kr = kr;
        this.cr = cr;
    }

    /** Writes the mirror direction of {@code wo} about the shading normal into {@code wi}. */
    public void sampleDirection(ShadeRec sr, Vec3 wo, Vec3 wi) {
        Vec3 n = sr.normal;
        double nDotWo = n.dot(wo);
        wi.set(-wo.x + 2 * nDotWo * n.x, -wo.y + 2 * nDotWo * n.y, -wo.z + 2 * nDotWo * n.z);
    }

    /** The reflected fraction kr cr: radiance along the mirror ray is multiplied by it. */
    public RGBColor reflectance() {
        return cr.scale(kr);
    }
}

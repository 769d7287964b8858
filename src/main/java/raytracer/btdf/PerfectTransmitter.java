package raytracer.btdf;

import raytracer.core.BTDF;
import raytracer.core.ShadeRec;
import raytracer.math.Vec3;

/**
 * Refraction by Snell's law at a smooth boundary between the outside (index 1) and a medium of
 * index {@code ior} (Suffern, section 27.2; pbrt-v3 section 8.2.3). Which way the light crosses
 * follows from {@code sr.frontFace}; the normal always faces {@code wo}.
 */
public final class PerfectTransmitter implements BTDF {
    private final double ior;

    public PerfectTransmitter(double ior) {
        if (!(ior > 0) || !Double.isFinite(ior)) {
            throw new IllegalArgumentException("index of refraction must be positive, got " + ior);
        }
        this.ior = ior;
    }

    /** The ratio eta_i / eta_t for light arriving on the side {@code wo} is on. */
    public double relativeEta(ShadeRec sr) {
        return sr.frontFace ? 1 / ior : ior;
    }

    @Override
    public boolean sampleDirection(ShadeRec sr, Vec3 wo, Vec3 wt) {
        Vec3 n = sr.normal;
        double eta = relativeEta(sr);
        double cosI = n.dot(wo);
        double sin2T = eta * eta * Math.max(0, 1 - cosI * cosI);
        if (sin2T >= 1) {
            return false;
        }
        double cosT = Math.sqrt(1 - sin2T);
        // wt = -eta wo + (eta cos_i - cos_t) n
        double k = eta * cosI - cosT;
        wt.set(-eta * wo.x + k * n.x, -eta * wo.y + k * n.y, -eta * wo.z + k * n.z);
        return true;
    }

    public double ior() {
        return ior;
    }
}

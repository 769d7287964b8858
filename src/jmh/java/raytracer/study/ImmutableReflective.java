package raytracer.study;

import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/**
 * {@link ImmutablePhong} plus a perfect mirror (Suffern, section 24.3): the radiance traced along the mirror
 * direction, times kr cr, added to the direct light; a new ray and new colours for every bounce.
 */
final class ImmutableReflective implements ImmutableMaterial {
    private final ImmutablePhong direct;
    /** kr cr. */
    private final RGBColor reflectance;

    ImmutableReflective(ImmutablePhong direct, RGBColor reflectance) {
        this.direct = direct;
        this.reflectance = reflectance;
    }

    @Override
    public RGBColor shade(Hit hit, ImmutableWhitted whitted) {
        RGBColor L = direct.shade(hit, whitted);
        int next = hit.depth() + 1;
        if (next > whitted.maxDepth()) {
            return L;
        }
        Vector3D n = hit.normal();
        Vector3D wo = hit.wo();
        // r = -wo + 2 (n . wo) n
        Vector3D wi = wo.negate().add(n.scale(2 * n.dot(wo)));
        Ray reflected = hit.spawnRay(wi);
        hit.record().scratch.secondaryRays++;
        RGBColor incoming = whitted.trace(reflected, next, hit.record().scratch);
        return L.add(incoming.mul(reflectance));
    }
}

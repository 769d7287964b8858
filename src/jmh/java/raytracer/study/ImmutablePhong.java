package raytracer.study;

import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * Ambient, diffuse and an optional Phong lobe under each light from its one direction (Suffern,
 * listings 14.11 and 15.4), every step a new value; without a lobe it is the book's Matte. The
 * steps are the renderer's (materials.DirectLighting.shade) in the same order, so the sums agree
 * to the bit.
 */
final class ImmutablePhong implements ImmutableMaterial {
    private final ImmutableLambertian ambient;
    private final ImmutableLambertian diffuse;
    private final ImmutableGlossySpecular specular;

    /** {@code specular} may be null: a matte surface. */
    ImmutablePhong(ImmutableLambertian ambient, ImmutableLambertian diffuse, ImmutableGlossySpecular specular) {
        this.ambient = ambient;
        this.diffuse = diffuse;
        this.specular = specular;
    }

    @Override
    public RGBColor shade(Hit hit, ImmutableWhitted whitted) {
        RGBColor L = ambient.rho().mul(whitted.ambient());
        for (ImmutableLight light : whitted.lights()) {
            ImmutableLight.Incidence incidence = light.incidence(hit);
            Vector3D wi = incidence.wi();
            double nDotWi = hit.normal().dot(wi);
            // the geometric normal decides which side the light is on, as in the renderer
            if (nDotWi <= 0 || hit.geometricNormal().dot(wi) <= 0) {
                continue;
            }
            RGBColor f = diffuse.f();
            RGBColor incident = light.L(hit);
            if (specular != null) {
                f = f.add(specular.f(hit, wi));
            }
            f = f.scale(nDotWi);
            if (light.castsShadows()) {
                ImmutableLight.ShadowRay shadowRay = light.shadowRay(hit, incidence);
                if (whitted.inShadow(shadowRay.ray(), shadowRay.tMax(), hit)) {
                    continue;
                }
            }
            L = L.add(f.mul(incident));
        }
        return L;
    }
}

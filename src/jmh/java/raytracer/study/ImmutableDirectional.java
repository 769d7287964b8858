package raytracer.study;

import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** Light from one direction with no falloff (Suffern, section 14.4.1). */
record ImmutableDirectional(Vector3D towardLight, RGBColor radiance, boolean castsShadows) implements ImmutableLight {

    @Override
    public Incidence incidence(Hit hit) {
        return new Incidence(towardLight, Double.POSITIVE_INFINITY);
    }

    @Override
    public ShadowRay shadowRay(Hit hit, Incidence incidence) {
        return new ShadowRay(hit.spawnRay(incidence.wi()), Double.POSITIVE_INFINITY);
    }

    @Override
    public RGBColor L(Hit hit) {
        return radiance;
    }
}

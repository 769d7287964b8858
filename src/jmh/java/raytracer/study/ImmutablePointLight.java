package raytracer.study;

import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** A point light of intensity I: irradiance I cos(theta) / r^2, so L is I / r^2, as the renderer's PointLight. */
record ImmutablePointLight(Point3D position, RGBColor intensity, boolean castsShadows) implements ImmutableLight {

    @Override
    public Incidence incidence(Hit hit) {
        Vector3D toLight = position.sub(hit.hitPoint());
        double distance = toLight.length();
        // divided, not scaled by 1 / distance, as the renderer's PointLight does
        return new Incidence(new Vector3D(toLight.x() / distance, toLight.y() / distance, toLight.z() / distance), distance);
    }

    @Override
    public ShadowRay shadowRay(Hit hit, Incidence incidence) {
        return new ShadowRay(hit.spawnRayTo(position), 1);
    }

    @Override
    public RGBColor L(Hit hit) {
        Vector3D toLight = position.sub(hit.hitPoint());
        return intensity.scale(1 / toLight.dot(toLight));
    }
}

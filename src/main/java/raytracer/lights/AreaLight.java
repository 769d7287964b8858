package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/**
 * An area light (Suffern, chapter 18): radiance Le leaves one side of a surface. Each shaded point
 * takes {@code samples} points of the surface, uniformly by area (pdf = 1 / area), and weighs each
 * by G / pdf = cos(theta_light) area / d^2, an unbiased estimate of the irradiance integral. Soft
 * shadows follow from the shadow ray of each sample.
 */
public final class AreaLight extends Light {
    private final Emitter emitter;
    private final RGBColor radiance;
    private final int samples;

    AreaLight(Emitter emitter, double ls, RGBColor color, int samples) {
        if (samples < 1) {
            throw new IllegalArgumentException("an area light needs at least 1 sample, got " + samples);
        }
        this.emitter = emitter;
        this.radiance = color.scale(ls);
        this.samples = samples;
    }

    public static AreaLight rectangle(raytracer.math.Point3D corner, raytracer.math.Vector3D a, raytracer.math.Vector3D b,
                                      double ls, RGBColor color, int samples) {
        return new AreaLight(new RectangleEmitter(corner, a, b), ls, color, samples);
    }

    public static AreaLight disk(raytracer.math.Point3D center, raytracer.math.Vector3D normal, double radius,
                                 double ls, RGBColor color, int samples) {
        return new AreaLight(new DiskEmitter(center, normal, radius), ls, color, samples);
    }

    public static AreaLight sphere(raytracer.math.Point3D center, double radius, double ls, RGBColor color, int samples) {
        return new AreaLight(new SphereEmitter(center, radius), ls, color, samples);
    }

    @Override
    public boolean hasExtent() {
        return true;
    }

    @Override
    public boolean mayIlluminate(ShadeRec sr) {
        return emitter.mayLight(sr.hitPoint, sr.normal) && emitter.mayLight(sr.hitPoint, sr.geometricNormal);
    }

    @Override
    public int sampleCount() {
        return samples;
    }

    @Override
    public double sample(ShadeRec sr, double u, double v, Vec3 wi) {
        emitter.sample(u, v, sr.lightPoint, sr.lightNormal);
        wi.set(sr.lightPoint.x - sr.hitPoint.x, sr.lightPoint.y - sr.hitPoint.y, sr.lightPoint.z - sr.hitPoint.z);
        double distance = wi.length();
        wi.set(wi.x / distance, wi.y / distance, wi.z / distance);
        return distance;
    }

    /** The centre of the emitter, for a single, unsampled direction. */
    @Override
    public double getDirection(ShadeRec sr, Vec3 wi) {
        return sample(sr, 0.5, 0.5, wi);
    }

    @Override
    public double geometryOverPdf(ShadeRec sr) {
        double dx = sr.lightPoint.x - sr.hitPoint.x;
        double dy = sr.lightPoint.y - sr.hitPoint.y;
        double dz = sr.lightPoint.z - sr.hitPoint.z;
        double d2 = dx * dx + dy * dy + dz * dz;
        double cosLight = -(sr.lightNormal.x * dx + sr.lightNormal.y * dy + sr.lightNormal.z * dz) / Math.sqrt(d2);
        return cosLight > 0 ? cosLight * emitter.area() / d2 : 0;
    }

    @Override
    public void L(ShadeRec sr, Rgb out) {
        out.set(radiance);
    }
}

package raytracer.lights;

import java.util.List;
import raytracer.core.Light;
import raytracer.core.Sampler;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * An area light (Suffern, chapter 18): radiance Le leaves one side of a surface. Each shaded point
 * takes {@code samples} points of the surface, and the AreaLighting tracer's areaLightShade weighs
 * each by Le f G cos(theta_i) / pdf with {@link #G} = cos(theta_light) / d^2 and {@link #pdf} the
 * sample's density over the light's area: the average is an unbiased estimate of the integral of
 * Le f cos(theta_i) over the solid angle the light covers. Soft shadows follow from the shadow ray
 * of each sample. The book samples uniformly by area (pdf = 1 / area); here a sphere, and a
 * rectangle that some object lies near, are sampled uniformly over the solid angle they cover at the
 * shaded point ({@link SphereEmitter}, {@link RectangleEmitter}), so that G / pdf is that solid
 * angle and only the cosine at the shaded point, the BRDF and the shadows vary between samples; a
 * disk, as in pbrt, and a rectangle far from everything by area.
 */
public final class AreaLight extends Light {
    private final Emitter emitter;
    private final RGBColor radiance;
    private final int samples;

    AreaLight(Emitter emitter, double ls, RGBColor color, int samples) {
        if (samples < 1 || samples > Sampler.MAX_SAMPLES) {
            throw new IllegalArgumentException("an area light takes 1 to " + Sampler.MAX_SAMPLES + " samples, got " + samples);
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

    /**
     * Fixes how a rectangle light draws its samples, by solid angle or by area, instead of letting
     * {@link #prepare} choose by what lies near it (the scene key {@code sampling}).
     */
    public void sampleBySolidAngle(boolean bySolidAngle) {
        if (!(emitter instanceof RectangleEmitter rectangle)) {
            throw new IllegalArgumentException("only a rectangle light has a choice of sampling");
        }
        rectangle.fix(bySolidAngle);
    }

    @Override
    public void prepare(List<BBox> receivers) {
        emitter.prepare(receivers);
    }

    @Override
    public boolean hasExtent() {
        return true;
    }

    /**
     * The emitter's area density times d^2 / cos(theta_light); where cos(theta_light) is 0 (a ray
     * along the light's plane, which cannot find it) infinite, so that a MIS weight leaves such a
     * direction to the other technique.
     */
    @Override
    public double directionPdf(double fromX, double fromY, double fromZ, double distance, double cosLight) {
        if (!(cosLight > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        return emitter.pdf(fromX, fromY, fromZ, distance, cosLight) * distance * distance / cosLight;
    }

    /** Le = ls c. */
    public RGBColor radiance() {
        return radiance;
    }

    /**
     * Both normals must see the emitter (the geometric one decides the side, as in the shading).
     * They are the same vector unless the normal is interpolated or bumped; then one test answers
     * for both, and a hit saves the second (a third of the shading's tests per light).
     */
    @Override
    public boolean mayIlluminate(ShadeRec sr) {
        MutableVec3 n = sr.normal;
        MutableVec3 g = sr.geometricNormal;
        boolean same = n.x == g.x && n.y == g.y && n.z == g.z;
        return emitter.mayLight(sr.hitPoint, n) && (same || emitter.mayLight(sr.hitPoint, g));
    }

    @Override
    public int sampleCount() {
        return samples;
    }

    /**
     * Samples the emitter as seen from the hit: the point, its normal and its area density are
     * kept in {@code sr} for {@link #G} and {@link #pdf}.
     */
    @Override
    public double sample(ShadeRec sr, double u, double v, MutableVec3 wi) {
        sr.lightPdf = emitter.sample(sr.hitPoint, u, v, sr.lightPoint, sr.lightNormal);
        wi.set(sr.lightPoint.x - sr.hitPoint.x, sr.lightPoint.y - sr.hitPoint.y, sr.lightPoint.z - sr.hitPoint.z);
        double distance = wi.length();
        wi.set(wi.x / distance, wi.y / distance, wi.z / distance);
        return distance;
    }

    /**
     * Refused: an area light has no single direction. Suffern's shade would take it as a point of
     * radiance Le and get the wrong units; its samples need areaLightShade, which the AreaLighting
     * tracer calls (the scene loader chooses that tracer for scenes with area lights).
     */
    @Override
    public double getDirection(ShadeRec sr, MutableVec3 wi) {
        throw new IllegalStateException("an area light is sampled, not seen from one direction: render with the "
                                        + "AreaLighting tracer (Suffern, chapter 18)");
    }

    /** cos(theta_light) / d^2 for the last sample; 0 when it faces away from the hit. */
    @Override
    public double G(ShadeRec sr) {
        return Emitter.geometricFactor(sr.hitPoint, sr.lightPoint, sr.lightNormal);
    }

    /**
     * The shadow ray ends at the sample's point moved off the emitter, towards its emitting side
     * where the hit lies, beyond the point's error bound ({@link Emitter#moveOff}), as
     * {@link ShadeRec#spawnRay} moves the hit's end: a surface in the light's plane, such as a
     * ceiling around its lamp, then lies beyond the ray's end and does not block it. The sample's
     * point in sr is moved in place: this is its last use.
     */
    @Override
    public boolean inShadow(ShadeRec sr, double distance) {
        MutableVec3 q = sr.lightPoint;
        emitter.moveOff(q, sr.lightNormal);
        return sr.world.shadowHit(sr.spawnRayTo(q.x, q.y, q.z, sr.scratch.shadowRay), 1, sr);
    }

    /** The last sample's density over the emitter's area, as its sampling gave it. */
    @Override
    public double pdf(ShadeRec sr) {
        return sr.lightPdf;
    }

    @Override
    public boolean isBlack() {
        return radiance.isBlack();
    }

    /** Its samples are a dimension of the pixel's ({@link raytracer.core.PixelSamples}), numbered by its place among the lights. */
    @Override
    public boolean drawsSamples() {
        return true;
    }

    @Override
    public boolean keepsShadowRaysWithin(HalfSpace h) {
        return h.contains(emitter.bounds());
    }

    @Override
    public String description() {
        return emitter.getClass().getSimpleName().replace("Emitter", "").toLowerCase(java.util.Locale.ROOT) + " light";
    }

    @Override
    public void L(ShadeRec sr, MutableRgb out) {
        out.set(radiance);
    }
}

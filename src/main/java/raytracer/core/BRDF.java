package raytracer.core;

import raytracer.math.MutableRgb;
import raytracer.math.SampleMapping;
import raytracer.math.MutableVec3;

/**
 * A bidirectional reflectance distribution function (Suffern, chapter 13): how much of the light
 * arriving from wi leaves towards wo. Directions are unit and point away from the surface; the
 * hemisphere is that of the shading normal {@code sr.normal}.
 */
public interface BRDF {

    /** Writes f(wo, wi) at the hit into {@code out}. */
    void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out);

    /**
     * Suffern's sample_f (chapters 24 and 25): picks a direction wi for the sample (u, v) in
     * [0,1)^2 with the density {@link #pdf}, writes it into {@code wi}, and writes into
     * {@code weight} the Monte Carlo weight f(wo, wi) cos(theta_i) / pdf(wi) by which the radiance
     * arriving along wi is multiplied. Returns false, with a black weight, when wi lies below the
     * surface: such a sample still counts in the average, which keeps the estimate unbiased.
     *
     * <p>The book returns f and the pdf and lets the material divide; here the BRDF divides, as
     * Mitsuba's BSDF::sample does, because f / pdf simplifies (cos^e cancels for a Phong lobe) and a
     * mirror's delta has no finite f to return.
     *
     * <p>This default samples the cosine-weighted hemisphere around the normal (Suffern, eq. 7.11
     * with e = 1: pdf = cos(theta_i) / pi, so the weight is pi f), which is unbiased for any f;
     * the book samples Lambertian reflection so (chapter 26). Lambertian, Ward and Blinn-Phong use
     * it; the lobes that trace rays (mirror, Phong) sample their own shape.
     */
    default boolean sampleF(ShadeRec sr, MutableVec3 wo, double u, double v, MutableVec3 wi, MutableRgb weight) {
        MutableVec3 n = sr.normal;
        SampleMapping.toHemisphere(u, v, 1, n.x, n.y, n.z, wi);
        if (!(n.dot(wi) > 0)) {
            weight.setBlack();
            return false;
        }
        f(sr, wo, wi, weight);
        weight.scale(Math.PI);
        return true;
    }

    /**
     * The solid-angle density with which {@link #sampleF} picks {@code wi}; 0 for every direction
     * of a delta distribution (a mirror), whose weight {@link #sampleF} gives instead. The default
     * is that of cosine sampling, cos(theta_i) / pi.
     */
    default double pdf(ShadeRec sr, MutableVec3 wo, MutableVec3 wi) {
        return SampleMapping.hemispherePdf(sr.normal.dot(wi), 1);
    }

    /** Writes the bihemispherical reflectance rho, used for ambient light, into {@code out}. */
    void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out);

    /** True when f and rho are exactly 0 for every hit and pair of directions (a kd or ks of 0, a black colour). */
    default boolean isBlack() {
        return false;
    }

    /** The same BRDF in a cheaper form where there is one (a constant texture read as a colour), else this. */
    default BRDF simplified() {
        return this;
    }
}

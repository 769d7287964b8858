package raytracer.core;

import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * A bidirectional transmittance distribution function (Suffern, chapter 27): how much of the light
 * arriving through the surface from wt leaves towards wo. Directions are unit; wo is on the side
 * the shading normal {@code sr.normal} faces, wt on the other.
 */
public interface BTDF {

    /** Writes f_t(wo, wt) into {@code out}; zero for a perfect transmitter, whose delta is sampled, never evaluated. */
    void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wt, MutableRgb out);

    /**
     * Suffern's sample_f (chapter 27): writes into {@code wt} a direction through the surface for
     * light leaving towards {@code wo} and into {@code weight} its Monte Carlo weight
     * f_t cos(theta_t) / pdf, by which the radiance arriving along wt is multiplied. Returns false,
     * with a black weight, when no light crosses (total internal reflection: the book's tir).
     */
    boolean sampleF(ShadeRec sr, MutableVec3 wo, MutableVec3 wt, MutableRgb weight);

    /** Writes the hemispherical transmittance rho into {@code out}; zero for a perfect transmitter, as in the book. */
    void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out);
}

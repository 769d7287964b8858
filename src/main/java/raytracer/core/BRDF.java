package raytracer.core;

import raytracer.math.Rgb;
import raytracer.math.Vec3;

/** A bidirectional reflectance distribution function (Suffern, chapter 13). */
public interface BRDF {

    /** Writes f(wo, wi) at the hit into {@code out}; both directions are unit and point away. */
    void f(ShadeRec sr, Vec3 wo, Vec3 wi, Rgb out);

    /** Writes the bihemispherical reflectance rho, used for ambient light, into {@code out}. */
    void rho(ShadeRec sr, Vec3 wo, Rgb out);
}

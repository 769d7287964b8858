package raytracer.core;

import raytracer.math.Vec3;

/** A bidirectional transmittance distribution function (Suffern, chapter 27): light through a surface. */
public interface BTDF {

    /**
     * Writes into {@code wt} the direction in which light from {@code wo} continues through the
     * surface at the hit; returns false when there is none (total internal reflection).
     */
    boolean sampleDirection(ShadeRec sr, Vec3 wo, Vec3 wt);
}

package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.MutableVec3;

/** The surface of an area light, sampled uniformly by area. */
interface Emitter {

    /** Writes the point for (u, v) in [0,1)^2 and the unit normal on its emitting side. */
    void sample(double u, double v, MutableVec3 point, MutableVec3 normal);

    double area();

    /**
     * Moves {@code point}, written by {@link #sample} with {@code normal}, off the emitter along the
     * normal, to the emitting side, beyond every point within the sample's rounding of the exact
     * surface the scene describes (and beyond the rounding of the move itself): a shadow ray that
     * ends there ends short of any surface in the emitter's plane.
     */
    void moveOff(MutableVec3 point, MutableVec3 normal);

    /** A box around every point of the emitter. */
    BBox bounds();

    /**
     * False only when no point of the emitter can light point {@code p} of a surface with unit
     * normal {@code n}: p is behind the emitting side, or the whole emitter lies below p's tangent
     * plane. Conservative: true may still mean that every sample weighs nothing.
     */
    boolean mayLight(MutableVec3 p, MutableVec3 n);
}

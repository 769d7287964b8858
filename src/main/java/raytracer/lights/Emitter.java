package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.MutableVec3;

/** The surface of an area light, sampled uniformly by area. */
interface Emitter {

    /** Writes the point for (u, v) in [0,1)^2 and the unit normal on its emitting side. */
    void sample(double u, double v, MutableVec3 point, MutableVec3 normal);

    double area();

    /**
     * A bound, on every axis, on how far a point written by {@link #sample} may lie from the exact
     * surface the scene describes: the rounding of the sample's arithmetic.
     */
    double pointError();

    /** A box around every point of the emitter. */
    BBox bounds();

    /**
     * False only when no point of the emitter can light point {@code p} of a surface with unit
     * normal {@code n}: p is behind the emitting side, or the whole emitter lies below p's tangent
     * plane. Conservative: true may still mean that every sample weighs nothing.
     */
    boolean mayLight(MutableVec3 p, MutableVec3 n);
}

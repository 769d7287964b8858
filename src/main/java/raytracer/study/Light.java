package raytracer.study;

import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** A light without extent (Suffern, chapter 14), answering in new values. */
interface Light {

    /** The unit direction from {@code hit} towards the light and the distance to it (infinite for a directional light). */
    Incidence incidence(Hit hit);

    /** The incident radiance at {@code hit} (for a point light, I / r^2). */
    RGBColor L(Hit hit);

    boolean castsShadows();

    /** Where light comes from: the book's get_direction, with the distance it computes on the way. */
    record Incidence(Vector3D wi, double distance) {
    }
}

package raytracer.study;

import raytracer.math.Ray;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** A light without extent (Suffern, chapter 14), answering in new values. */
interface ImmutableLight {

    /** The unit direction from {@code hit} towards the light and the distance to it (infinite for a directional light). */
    Incidence incidence(Hit hit);

    /** The incident radiance at {@code hit} (for a point light, I / r^2). */
    RGBColor L(Hit hit);

    boolean castsShadows();

    /** The shadow ray from {@code hit} towards the light along {@code incidence}, as the renderer's Light.inShadow makes it. */
    ShadowRay shadowRay(Hit hit, Incidence incidence);

    /** A shadow ray and how far it runs: to t = 1 when aimed at the light's point, to infinity for a directional light. */
    record ShadowRay(Ray ray, double tMax) {
    }

    /** Where light comes from: the book's get_direction, with the distance it computes on the way. */
    record Incidence(Vector3D wi, double distance) {
    }
}

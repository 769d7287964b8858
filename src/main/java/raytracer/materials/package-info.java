/**
 * Materials (Suffern, chapters 14, 15, 18, 24, 25 and 28): each combines BRDFs (and a BTDF) and
 * says how a hit is shaded, in the book's two forms: {@code shade} for the RayCast and Whitted
 * tracers, {@code areaLightShade} for the AreaLighting tracer.
 */
package raytracer.materials;

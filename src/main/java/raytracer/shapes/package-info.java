/**
 * Analytic shapes (Suffern, chapters 3, 19 and 21): sphere, plane, axis-aligned box, cylinder,
 * triangle, and {@link raytracer.shapes.Instance} for an object under an affine transform. Every
 * {@code completeHit} also bounds the rounding error of the hit point it computes, so that secondary
 * rays can start just off the surface at any scene scale.
 */
package raytracer.shapes;

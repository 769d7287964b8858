/**
 * Light sources (Suffern, chapters 14 and 18): ambient, point (inverse-square falloff),
 * directional, and area lights (rectangle, disk, sphere) weighed by the book's G and pdf: a
 * rectangle sampled over the solid angle it covers where it is near or large (Urena et al. 2013),
 * a sphere over the cone it fills, a disk and any other parallelogram by area.
 */
package raytracer.lights;

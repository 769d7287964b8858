/**
 * Light sources (Suffern, chapters 14 and 18): ambient, point (inverse-square falloff),
 * directional, and area lights (rectangle, disk, sphere) weighed by the book's G and pdf: a
 * rectangle sampled over the solid angle it covers (Urena et al. 2013) when an object lies near it,
 * a sphere over the cone it fills, a disk, any other parallelogram and a rectangle far from
 * everything by area.
 */
package raytracer.lights;

/**
 * Light sources (Suffern, chapters 14 and 18): ambient, point (inverse-square falloff),
 * directional, and area lights (rectangle, disk, sphere) sampled uniformly by area with the book's
 * G and pdf.
 */
package raytracer.lights;

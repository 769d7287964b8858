/**
 * Sample patterns in the unit square (Suffern, chapter 5): regular, random, jittered, n-rooks,
 * multi-jittered and Hammersley. Each draws a fresh pattern per pixel from the pixel's generator.
 */
package raytracer.samplers;

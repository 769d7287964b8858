/**
 * Sample patterns in the unit square (Suffern, chapter 5): regular, random, jittered, n-rooks,
 * multi-jittered and Hammersley, and the Owen-scrambled Sobol sequence. The renderer's
 * {@link raytracer.core.PixelSamples} draws one pattern per pixel and dimension from a generator
 * seeded by both, or asks a pointwise sampler (random, Sobol) for single points.
 */
package raytracer.samplers;

/**
 * Sample patterns in the unit square (Suffern, chapter 5): regular, random, jittered, n-rooks,
 * multi-jittered and Hammersley, and the Owen-scrambled Sobol sequence. A render makes up to 1,024
 * patterns of each size once ({@link raytracer.core.SampleTables}), each from a generator of its
 * own, and the renderer's {@link raytracer.core.PixelSamples} picks one pattern and one shuffle
 * for each pixel and dimension by hashing both.
 */
package raytracer.samplers;

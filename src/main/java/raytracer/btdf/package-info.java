/**
 * Transmission models (Suffern, chapters 27 and 28): the perfect, specular transmitter of smooth
 * glass, with f, sample_f ({@code sampleF}) and rho.
 */
package raytracer.btdf;

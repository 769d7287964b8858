/** Transmission models (Suffern, chapter 27): the perfect, specular transmitter of smooth glass. */
package raytracer.btdf;

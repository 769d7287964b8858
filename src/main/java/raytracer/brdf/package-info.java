/**
 * Reflectance models (Suffern, chapters 13, 15, 24 and 25): Lambertian, Phong's glossy lobe, the
 * perfect mirror, and the fitted Ward and Blinn-Phong lobes of the report's figure 2. Each gives
 * f, sample_f ({@code sampleF}), pdf and rho.
 */
package raytracer.brdf;

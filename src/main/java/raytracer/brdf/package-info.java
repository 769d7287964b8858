/** Reflectance models (Suffern, chapters 13, 15 and 24): Lambertian, Phong's glossy lobe, perfect mirror. */
package raytracer.brdf;

/** Rasters and their encodings: the linear film, tone mapping to sRGB, PNG and PFM writers, atomic output. */
package raytracer.image;

/**
 * Pixel filters beyond the book's box ({@link raytracer.core.PixelFilter#BOX}): the Gaussian, and
 * the names scene files use for them.
 */
package raytracer.filters;

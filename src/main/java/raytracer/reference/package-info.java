/**
 * Exact images for scenes that have one, to measure the renderer's true error: the irradiance of a
 * polygonal light (Lambert's formula) and of a disk parallel to the receiver, averaged over each
 * pixel of a diffuse plane seen by an orthographic camera. Independent of the renderer's code.
 */
package raytracer.reference;

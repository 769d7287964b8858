/** Cameras (Suffern, chapters 8-10): pinhole, thin lens for depth of field, and orthographic. */
package raytracer.cameras;

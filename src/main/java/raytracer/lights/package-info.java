/** Light sources (Suffern, chapter 14): ambient, point (inverse-square falloff) and directional. */
package raytracer.lights;

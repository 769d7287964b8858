/**
 * Textures (Suffern, chapters 29-31): constant, checker and image textures looked up by the hit's
 * u, v, and equirectangular environment maps looked up by direction.
 */
package raytracer.textures;

/** Materials (Suffern, chapters 14, 15 and 24): each combines BRDFs and says how a hit is shaded. */
package raytracer.materials;

/** Tracers (Suffern, chapters 3 and 24): ray casting without recursion, and Whitted's recursive tracer. */
package raytracer.tracers;

/**
 * Rendering an image: a ForkJoin pool over tiles, one {@link raytracer.core.WorkerScratch} per worker
 * thread, per-pixel seeded sampling (so the image is identical for any thread count), progress and
 * statistics. Sees only the {@code core} interfaces.
 */
package raytracer.render;

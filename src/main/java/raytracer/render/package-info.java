/**
 * Rendering an image: the run's one fork/join pool ({@link raytracer.render.Workers}, which also
 * loads the scene and builds its BVHs), tiles split over it, one {@link raytracer.core.WorkerScratch}
 * per worker thread, per-pixel seeded sampling (so the image is identical for any thread count),
 * the Gaussian filter's per-tile sums ({@link raytracer.render.FilteredTile}), added in tile order,
 * progress, finished tiles told to a preview ({@link raytracer.render.TileListener}) and statistics. Sees only the {@code core} interfaces.
 */
package raytracer.render;

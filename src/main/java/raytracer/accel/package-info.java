/**
 * Acceleration structures (report section 6): a bounding volume hierarchy stored flat in arrays,
 * built by the report's sorted-median split or by the binned surface area heuristic, over the
 * triangles of a mesh ({@link raytracer.accel.MeshBVH}) or over ordinary objects
 * ({@link raytracer.accel.ObjectBVH}).
 */
package raytracer.accel;

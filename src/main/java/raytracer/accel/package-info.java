/**
 * Acceleration structures (report section 6): a bounding volume hierarchy flattened into arrays
 * ({@link raytracer.accel.FlatBVH}, its node layout in {@code BvhNodes}) with one traversal for
 * closest and any hit; over the triangles of a mesh ({@link raytracer.accel.MeshBVH}) or over
 * ordinary objects ({@link raytracer.accel.ObjectBVH}). Built by the report's sorted-median split,
 * as written ({@link raytracer.accel.SortedMedianBuilder}) or as the renderer runs it, the same
 * tree by median selection ({@link raytracer.accel.MedianSplitBuilder}), or by the binned surface
 * area heuristic in parallel ({@link raytracer.accel.SahBuilder}, its bins in {@code SahBins}), each
 * as a {@code BinaryTree} that {@code flat} packs into the searched layout;
 * {@link raytracer.accel.SahCost} says what a tree is expected to cost a ray.
 * {@link raytracer.accel.Aggregation} decides what the world searches through a BVH.
 */
package raytracer.accel;

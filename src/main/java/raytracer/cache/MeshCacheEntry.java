package raytracer.cache;

import raytracer.accel.FlatBVH;
import raytracer.shapes.mesh.Mesh;

/** A whole mesh cache entry as read back and checked: its header, its mesh (in its tree's leaf order) and its tree. */
public record MeshCacheEntry(MeshCacheHeader header, Mesh mesh, FlatBVH bvh) {
}

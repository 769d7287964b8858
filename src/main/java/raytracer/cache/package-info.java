/**
 * Files this program keeps between runs to reuse work, and what the two caches share. The mesh
 * cache ({@link raytracer.cache.MeshCache}): parsed meshes with their BVHs, one file each
 * ({@link raytracer.cache.MeshCacheFile}, its header {@link raytracer.cache.MeshCacheHeader},
 * streamed through {@link raytracer.cache.ChecksummedOutput} and {@link raytracer.cache.ChecksummedInput}),
 * which the scene reader looks up and stores through ({@link raytracer.cache.MeshCacheLookup}).
 * The reference cache ({@link raytracer.cache.ReferenceCache}): converge's self-rendered
 * references. Shared: a folder kept under its cap without touching anything the program cannot
 * prove it wrote ({@link raytracer.cache.CacheFolder}) and its default place
 * ({@link raytracer.cache.CacheHome}), entry names ({@link raytracer.cache.EntryName}), a file's
 * content identity ({@link raytracer.cache.ContentStamp}) and the one digest behind all of them,
 * CRC-32C with CRC-32 ({@link raytracer.cache.Checksum}).
 */
package raytracer.cache;

/**
 * Triangle meshes over flat primitive arrays (as Sunflow does): one object for a million triangles,
 * not a million objects. {@link raytracer.shapes.mesh.Mesh} holds the data (positions as doubles
 * for the watertight test, normals and texture coordinates as floats);
 * {@link raytracer.shapes.mesh.TriangleMesh} is the mesh as an object: each triangle's hit test
 * and the completion of a hit. Searching a large mesh quickly is the business of
 * {@code accel.MeshBVH}, which this package does not know.
 */
package raytracer.shapes.mesh;

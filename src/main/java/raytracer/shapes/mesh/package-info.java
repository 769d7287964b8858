/**
 * Triangle meshes over flat primitive arrays (as Sunflow does): one object for a million triangles,
 * not a million objects. Positions are doubles for the watertight test; normals and texture
 * coordinates are floats.
 */
package raytracer.shapes.mesh;

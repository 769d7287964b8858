/**
 * Stanford PLY meshes (Turk, "The PLY Polygon File Format", 1994), as the Stanford 3D Scanning
 * Repository and Suffern's book read them: an ASCII header naming elements and their typed
 * properties, then a body in ASCII or binary of either byte order. The {@code vertex} element's
 * positions, normals and texture coordinates and the {@code face} element's vertex lists become one
 * {@link raytracer.shapes.mesh.Mesh}; every other element and property is read past. A file that
 * plyfile, trimesh and tinyply all read is read with the triangles they read; what some of them
 * read past (a header line of an unknown keyword, a face of fewer than three corners, data after
 * the last element) is a warning; a value that does not fit its declared type is an error, as in
 * rply and plyfile. Errors name the file and the header line, or the element, its row and, in
 * ASCII, the line.
 */
package raytracer.io.ply;

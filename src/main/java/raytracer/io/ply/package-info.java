/**
 * Stanford PLY meshes (Turk, "The PLY Polygon File Format", 1994), as the Stanford 3D Scanning
 * Repository and Suffern's book read them: an ASCII header naming elements and their typed
 * properties, then a body in ASCII or binary of either byte order. The {@code vertex} element's
 * positions, normals and texture coordinates and the {@code face} element's vertex lists become one
 * {@link raytracer.shapes.mesh.Mesh}; every other element and property is read past. Errors name
 * the file and the header line or the element and its number.
 */
package raytracer.io.ply;

package raytracer.io.obj;

import raytracer.shapes.mesh.Growing;

/**
 * What a parse of an OBJ file read, as {@link MeshAssembly} makes the mesh of it: the v, vt and vn
 * lines' values in file order, and each triangle corner's v, vt and vn numbers (vt and vn null
 * when no face gave them), with a material id per triangle (null without usemtl).
 */
record ObjArrays(Growing.Doubles positions, Growing.Floats texcoords, Growing.Floats normals, Growing.Ints cornerV,
                 Growing.Ints cornerVt, Growing.Ints cornerVn, int[] materialIds) {
}

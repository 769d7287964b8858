package raytracer.io.obj;

import java.util.List;
import raytracer.shapes.mesh.Mesh;

/** What an OBJ file holds: one mesh, its materials (indexed by the mesh's material ids) and warnings. */
public record ObjModel(Mesh mesh, List<ObjMaterial> materials, List<String> warnings) {
}

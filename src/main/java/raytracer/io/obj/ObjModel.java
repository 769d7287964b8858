package raytracer.io.obj;

import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import raytracer.shapes.mesh.Mesh;

/**
 * What an OBJ file holds: one mesh, its materials (indexed by the mesh's material ids) and
 * warnings; {@code faces} as written and how many of them had more than three corners ({@code ngons});
 * {@code libraries}, the MTL files it read (what else a copy of the model depends on); {@code sheets},
 * the ids of the see-through materials whose triangles are open sheets rather than the surface of
 * a solid ({@link OpenSheets}).
 */
public record ObjModel(Mesh mesh, List<ObjMaterial> materials, List<String> warnings, int faces, int ngons,
                       List<Path> libraries, Set<Integer> sheets) {
}

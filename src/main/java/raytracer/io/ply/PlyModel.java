package raytracer.io.ply;

import java.util.List;
import raytracer.shapes.mesh.Mesh;

/** What a PLY file holds: one mesh, the warnings of its load, its faces as written and how many had more than three corners. */
public record PlyModel(Mesh mesh, List<String> warnings, int faces, int ngons) {
}

package raytracer.io.obj;

import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.ParsedMesh;

/**
 * What an OBJ file holds: one mesh ({@code parsed}, in the file's order, its positions still in
 * the parse's blocks; {@link #mesh} a flat copy), its materials (indexed by the mesh's material ids) and
 * warnings; {@code faces} as written and how many of them had more than three corners ({@code ngons});
 * {@code libraries}, the MTL files it read (what else a copy of the model depends on); {@code sheets},
 * the ids of the see-through materials whose triangles are open sheets rather than the surface of
 * a solid ({@link OpenSheets}).
 */
public record ObjModel(ParsedMesh parsed, List<ObjMaterial> materials, List<String> warnings, int faces, int ngons,
                       List<Path> libraries, Set<Integer> sheets) {
    /** The mesh in file order, its positions copied flat: for a look at it (a BVH is built over {@link #parsed}). */
    public Mesh mesh() {
        return parsed.mesh();
    }

    /** This model without its mesh, once the mesh is handed over: its figures, materials and warnings. */
    public ObjModel withoutMesh() {
        return new ObjModel(null, materials, warnings, faces, ngons, libraries, sheets);
    }
}

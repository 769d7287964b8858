package raytracer.io.ply;

import java.util.List;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.ParsedMesh;

/**
 * What a PLY file holds: one mesh ({@code parsed}, in the file's order; {@link #mesh} a flat copy),
 * warnings, the faces read (those of fewer than three corners are skipped) and how many of them
 * had more than three corners.
 */
public record PlyModel(ParsedMesh parsed, List<String> warnings, int faces, int ngons) {
    /** The mesh in file order, its positions copied flat. */
    public Mesh mesh() {
        return parsed.mesh();
    }
}

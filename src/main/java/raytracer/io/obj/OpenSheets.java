package raytracer.io.obj;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import raytracer.shapes.mesh.ParsedMesh;

/**
 * Which see-through material groups of a mesh are open sheets (a window pane, a glass quad) rather
 * than the closed surface of a solid: a group is open when one of its edges belongs to only one of
 * its triangles. Only a closed surface bounds an inside that a refracted ray can cross and leave;
 * a sheet seen from behind would be taken as the inside of a medium. Corners are joined by
 * position, since a closed surface written with per-face normals or texture coordinates has its
 * corners split into vertices that share one. Each group is judged by its own triangles (a
 * glass body closed by a cap of another material is open), and only see-through groups are
 * looked at, so that a large opaque mesh costs nothing.
 */
final class OpenSheets {
    private OpenSheets() {
    }

    /** The material ids (indices into {@code materials}) of the see-through groups of {@code mesh} that are open. */
    static Set<Integer> of(ParsedMesh mesh, List<ObjMaterial> materials) {
        Set<Integer> open = new TreeSet<>();
        int[] ids = mesh.materialIds();
        for (int id = 0; id < materials.size(); id++) {
            if (materials.get(id).seeThrough() && hasBoundaryEdge(mesh, ids, id)) {
                open.add(id);
            }
        }
        return Set.copyOf(open);
    }

    /** Whether some edge of the triangles of material {@code id} (all of them when {@code ids} is null) is used once. */
    private static boolean hasBoundaryEdge(ParsedMesh mesh, int[] ids, int id) {
        Map<Corner, Integer> welded = new HashMap<>();
        Map<Long, Integer> uses = new HashMap<>();
        int[] corner = new int[3];
        for (int tri = 0; tri < mesh.triangleCount(); tri++) {
            if (ids != null && ids[tri] != id) {
                continue;
            }
            for (int k = 0; k < 3; k++) {
                corner[k] = weld(mesh, mesh.corner(tri, k), welded);
            }
            for (int k = 0; k < 3; k++) {
                int a = corner[k];
                int b = corner[(k + 1) % 3];
                if (a != b) {
                    uses.merge(((long) Math.min(a, b) << 32) | Math.max(a, b), 1, Integer::sum);
                }
            }
        }
        return uses.containsValue(1);
    }

    /** The number of the first corner seen at the position at {@code offset} into the mesh's positions. */
    private static int weld(ParsedMesh mesh, int offset, Map<Corner, Integer> welded) {
        // + 0.0 makes -0.0 the same position as 0.0
        Corner key = new Corner(mesh.position(offset) + 0.0, mesh.position(offset + 1) + 0.0, mesh.position(offset + 2) + 0.0);
        return welded.computeIfAbsent(key, k -> welded.size());
    }

    /** A position as a map key. */
    private record Corner(double x, double y, double z) {
    }
}

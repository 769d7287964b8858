package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Which see-through material groups of an OBJ file are open sheets, and which close around a solid. */
class OpenSheetsTest {
    @TempDir
    Path dir;

    /** The eight corners of the cube [0, 1]^3, numbered 1..8 as OBJ counts. */
    private static final String CUBE_CORNERS = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    /** Its six faces, wound outwards. */
    private static final String[] CUBE_FACES = {"1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"};

    /** The names of the materials the loader found open, for the OBJ {@code body} under an MTL of glass, window and paint. */
    private Set<String> open(String body) throws IOException, ObjException {
        Files.writeString(dir.resolve("m.mtl"), "newmtl glass\nd 0.1\nNi 1.5\nnewmtl window\nTr 0.9\nnewmtl paint\nKd 0.5 0.5 0.5\n");
        ObjModel model = ObjLoader.load(Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\n" + body), false);
        Set<String> names = new TreeSet<>();
        List<ObjMaterial> materials = model.materials();
        for (int id : model.sheets()) {
            names.add(materials.get(id).name());
        }
        return names;
    }

    private static String cube(String material, int offset, boolean normals) {
        StringBuilder obj = new StringBuilder("usemtl " + material + "\n");
        for (int f = 0; f < CUBE_FACES.length; f++) {
            obj.append("f");
            for (String corner : CUBE_FACES[f].split(" ")) {
                obj.append(' ').append(Integer.parseInt(corner) + offset).append(normals ? "//" + (f + 1) : "");
            }
            obj.append('\n');
        }
        return obj.toString();
    }

    private static final String NORMALS = "vn -0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n";

    @Test
    void aGlassQuadIsAnOpenSheet() throws Exception {
        assertEquals(Set.of("glass"), open("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl glass\nf 1 2 3 4\n"));
        assertEquals(Set.of("window"), open("v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl window\nf 1 2 3\n"), "Tr 0.9 is see-through");
    }

    @Test
    void aClosedGlassCubeIsASolidHoweverItsCornersAreWritten() throws Exception {
        assertEquals(Set.of(), open(CUBE_CORNERS + cube("glass", 0, false)));
        // per-face normals split each corner into three vertices of one position
        assertEquals(Set.of(), open(CUBE_CORNERS + NORMALS + cube("glass", 0, true)));
        // every face with corners of its own, written again
        StringBuilder apart = new StringBuilder("usemtl glass\n");
        for (String face : CUBE_FACES) {
            for (String c : face.split(" ")) {
                apart.append(CUBE_CORNERS.split("\n")[Integer.parseInt(c) - 1]).append('\n');
            }
            apart.append("f -4 -3 -2 -1\n");
        }
        assertEquals(Set.of(), open(apart.toString()));
    }

    @Test
    void aCubeWithoutItsLidIsOpen() throws Exception {
        String cube = cube("glass", 0, false);
        String withoutLid = cube.replace("f 3 4 8 7\n", "");
        assertEquals(Set.of("glass"), open(CUBE_CORNERS + withoutLid));
    }

    @Test
    void eachGroupIsJudgedOnItsOwnAndOpaqueOnesAreNotJudged() throws Exception {
        // a closed glass cube, a window pane beside it, a painted quad: only the pane is an open sheet
        String pane = "v 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\nusemtl window\nf 9 10 11 12\nusemtl paint\nf 9 10 11\n";
        assertEquals(Set.of("window"), open(CUBE_CORNERS + cube("glass", 0, false) + pane));
        // the cube's lid in another material leaves the glass open, though the mesh is closed
        String lid = cube("glass", 0, false).replace("f 3 4 8 7\n", "usemtl paint\nf 3 4 8 7\n");
        assertEquals(Set.of("glass"), open(CUBE_CORNERS + lid));
    }
}

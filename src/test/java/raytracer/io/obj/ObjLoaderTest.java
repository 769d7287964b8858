package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.shapes.mesh.Mesh;

class ObjLoaderTest {
    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    private ObjModel load(String text) throws IOException, ObjException {
        return ObjLoader.load(write("m.obj", text), false);
    }

    private String error(String text) throws IOException {
        ObjException e = assertThrows(ObjException.class, () -> ObjLoader.load(write("bad.obj", text), false));
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
        return e.getMessage();
    }

    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    @Test
    void allFourFaceFormsAndNegativeIndices() throws Exception {
        ObjModel m = load(SQUARE + "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
            + "f 1 2 3\n"            // v
            + "f 1/1 2/2 3/3\n"      // v/vt
            + "f 1//1 2//1 3//1\n"   // v//vn
            + "f -4/-3/-1 -3/-2/-1 -2/-1/-1\n" // v/vt/vn, relative
            + "f 1/1/1 2/2/1 3/3/1\n"); // the same triples again, absolute
        Mesh mesh = m.mesh();
        assertEquals(5, mesh.triangleCount());
        assertTrue(mesh.hasUvs() && mesh.hasNormals());
        // the relative face names vertices 1, 2, 3, texture coordinates 1, 2, 3 and normal 1
        double[][] positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
        float[][] uvs = {{0, 0}, {1, 0}, {1, 1}};
        for (int k = 0; k < 3; k++) {
            int v = mesh.vertex(3, k);
            assertArrayEquals(positions[k], Arrays.copyOfRange(mesh.positions(), 3 * v, 3 * v + 3), 0);
            assertArrayEquals(uvs[k], Arrays.copyOfRange(mesh.uvs(), 2 * v, 2 * v + 2), 0);
            assertEquals(1f, mesh.normals()[3 * v + 2]);
        }
        // the same (v, vt, vn) triple is one mesh vertex, however its indices are written
        for (int k = 0; k < 3; k++) {
            assertEquals(mesh.vertex(3, k), mesh.vertex(4, k), "corner " + k);
            assertNotEquals(mesh.vertex(1, k), mesh.vertex(3, k), "faces 2 and 4 differ in vn");
        }
        assertTrue(mesh.vertexCount() <= 12, "at most one vertex per distinct triple: " + mesh.vertexCount());
    }

    @Test
    void positionOnlyMeshesKeepTheirVertexArray() throws Exception {
        Mesh mesh = load(SQUARE + "f 1 2 3 4\n").mesh();
        assertEquals(4, mesh.vertexCount());
        assertEquals(2, mesh.triangleCount(), "a quad is fan-triangulated");
        assertEquals(0, mesh.vertex(1, 0));
        assertEquals(2, mesh.vertex(1, 1));
        assertEquals(3, mesh.vertex(1, 2));
        assertNull(mesh.normals(), "flat unless smooth normals are asked for");
    }

    @Test
    void ngonsCommentsBlankLinesGroupsContinuationAndCrlf() throws Exception {
        String text = "# a comment\r\n\r\n   \r\no hexagon\r\ng group1 group2\r\ns 1\r\n"
            + "v 1 0 0 1.0\r\nv 0.5 0.87 0 0.2 0.3 0.4\r\nv -0.5 0.87 0\r\nv -1 0 0\r\nv -0.5 -0.87 0\r\nv 0.5 -0.87 0\r\n"
            + "f 1 2 3 \\\r\n 4 5 6 # the hexagon\r\ns off\r\n";
        ObjModel m = load(text);
        assertEquals(4, m.mesh().triangleCount());
        assertEquals(6, m.mesh().vertexCount());
        assertEquals(-0.87, m.mesh().positions()[3 * 4 + 1], 0);
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
    }

    @Test
    void numbersParseExactly() throws Exception {
        Mesh mesh = load("v 0.1 -2.5e-3 +1E2\nv 123456.789 .5 -0.0\nv 1e-30 9007199254740993 3\nf 1 2 3\n").mesh();
        double[] expected = {0.1, -2.5e-3, 100, 123456.789, 0.5, -0.0, 1e-30, 9007199254740993.0, 3};
        assertArrayEquals(expected, mesh.positions(), 0);
    }

    @Test
    void materialsFromTheLibraryWithTexturesAndOptions() throws Exception {
        Files.write(dir.resolve("wood.png"), new byte[] {1});
        Files.write(dir.resolve("bumps.png"), new byte[] {1});
        write("lib.mtl", "# library\nnewmtl wood\nKd 0.6 0.4 0.2\nKs 0.1 0.1 0.1\nNs 32\nd 0.9\nNi 1.45\nillum 2\n"
            + "map_Kd -s 1 1 1 wood.png\nmap_Bump -bm 0.5 bumps.png\nnewmtl glass\nKd 1\nTr 0.75\nNi 1.5\nfoo 1\n");
        ObjModel m = load("mtllib lib.mtl\n" + SQUARE + "f 1 2 3\nusemtl wood\nf 1 3 4\nusemtl glass\nf 2 3 4\nusemtl wood\nf 1 2 4\n");
        assertEquals(3, m.materials().size(), "(default) for the face before usemtl, wood, glass");
        assertArrayEquals(new int[] {0, 1, 2, 1}, m.mesh().materialIds());
        ObjMaterial wood = m.materials().get(1);
        assertEquals("wood", wood.name());
        assertArrayEquals(new double[] {0.6, 0.4, 0.2}, wood.kd(), 0);
        assertEquals(32, wood.ns(), 0);
        assertEquals(0.9, wood.dissolve(), 0);
        assertEquals(1.45, wood.ior(), 0);
        assertEquals(dir.resolve("wood.png"), wood.mapKd());
        assertEquals(dir.resolve("bumps.png"), wood.mapBump());
        assertEquals(0.5, wood.bumpScale(), 0);
        ObjMaterial glass = m.materials().get(2);
        assertArrayEquals(new double[] {1, 1, 1}, glass.kd(), 0);
        assertEquals(0.25, glass.dissolve(), 1e-15);
        assertEquals(1, m.warnings().size(), m.warnings().toString());
        assertTrue(m.warnings().get(0).contains("lib.mtl:15") && m.warnings().get(0).contains("'foo'"));
    }

    @Test
    void aBackslashOnTheLastLineEndsIt() throws Exception {
        for (String end : new String[] {"f 1 2 3 \\", "f 1 2 \\\n3 \\", "f 1 2 3 \\\n"}) {
            ObjModel m = load(SQUARE + end);
            assertEquals(1, m.mesh().triangleCount(), end);
            assertEquals(2, m.mesh().vertex(0, 2), end);
        }
    }

    @Test
    void bumpAndNormAreNamesForTheNormalMap() throws Exception {
        Files.write(dir.resolve("n.png"), new byte[] {1});
        write("lib.mtl", "newmtl a\nbump n.png\nnewmtl b\nnorm n.png\nnewmtl c\nmap_bump -bm 2 n.png\n");
        ObjModel m = load("mtllib lib.mtl\n" + SQUARE + "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\nusemtl c\nf 2 3 4\n");
        assertEquals(3, m.materials().size());
        for (ObjMaterial material : m.materials()) {
            assertEquals(dir.resolve("n.png"), material.mapBump(), material.name());
        }
        assertEquals(2, m.materials().get(2).bumpScale(), 0);
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
    }

    @Test
    void missingLibraryAndTextureAreWarningsNotFailures() throws Exception {
        write("lib.mtl", "newmtl m\nKd 1 0 0\nmap_Kd nowhere.png\n");
        ObjModel m = load("mtllib lib.mtl missing.mtl\n" + SQUARE + "usemtl m\nf 1 2 3\nusemtl ghost\nf 1 3 4\n");
        assertEquals(2, m.mesh().triangleCount());
        String all = String.join("\n", m.warnings());
        assertTrue(all.contains("nowhere.png") && all.contains("missing"), all);
        assertTrue(all.contains("missing.mtl"), all);
        assertTrue(all.contains("'ghost'"), all);
        assertNull(m.materials().get(0).mapKd());
        assertArrayEquals(new double[] {1, 0, 0}, m.materials().get(0).kd(), 0);
    }

    @Test
    void gzipIsReadTransparently() throws Exception {
        Path gz = dir.resolve("m.obj.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(gz))) {
            out.write((SQUARE + "f 1 2 3 4\n").getBytes(StandardCharsets.UTF_8));
        }
        assertEquals(2, ObjLoader.load(gz, false).mesh().triangleCount());
    }

    @Test
    void truncatedGzipNamesTheFile() throws Exception {
        Path gz = dir.resolve("cut.obj.gz");
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(gz))) {
            for (int i = 0; i < 2000; i++) {
                out.write(("v " + i + " " + (i * 7 % 13) + " 0.5\n").getBytes(StandardCharsets.UTF_8));
            }
        }
        byte[] all = Files.readAllBytes(gz);
        Files.write(gz, Arrays.copyOf(all, all.length / 2));
        ObjException e = assertThrows(ObjException.class, () -> ObjLoader.load(gz, false));
        assertTrue(e.getMessage().contains("cut.obj.gz") && e.getMessage().contains("truncated"), e.getMessage());
    }

    @Test
    void badInputNamesFileLineAndWhatWasExpected() throws IOException {
        assertTrue(error(SQUARE + "f 1 2 5\n").startsWith(dir.resolve("bad.obj") + ":5: vertex index 5 is out of range"));
        assertTrue(error(SQUARE + "f 1 2 -5\n").contains(":5: vertex index -5 is out of range"));
        assertTrue(error(SQUARE + "f 0 1 2\n").contains(":5: vertex index 0 is out of range"));
        // a texture coordinate or normal that does not exist is a warning: ObjFacesTest
        // a face of fewer than 3 corners is skipped with a warning: ObjFacesTest
        assertTrue(error("v 1 2 x\n").contains("bad.obj:1: expected 'v x y z' with three numbers, got 'v 1 2 x'"));
        assertTrue(error("v 1 2\n").contains(":1: expected 'v x y z'"));
        assertTrue(error("v 1 nan 2\n").contains(":1: coordinate 'nan' is not a finite number"));
        assertTrue(error("v 1 2 inf\n").contains(":1: coordinate 'inf' is not a finite number"));
        assertTrue(error("v 1 2 1e400\n").contains(":1: coordinate '1e400' is not a finite number"));
        assertTrue(error("v 1 2 1e99999999999\n").contains(":1: coordinate '1e99999999999' is not a finite number"),
                   error("v 1 2 1e99999999999\n"));
        assertTrue(error("vn 0 0\n").contains(":1: expected 'vn x y z'"));
        assertTrue(error(SQUARE + "f 1 a 3\n").contains(":5: expected 'f'"));
        assertTrue(error("").contains("no faces"));
        assertTrue(error("# nothing\n" + SQUARE).contains("no faces"));
        ObjException missing = assertThrows(ObjException.class, () -> ObjLoader.load(dir.resolve("none.obj"), false));
        assertTrue(missing.getMessage().contains("none.obj") && missing.getMessage().contains("no such file"));
    }

    @Test
    void smoothNormalsAreAngleWeighted() throws Exception {
        // a unit cube corner split into triangles unevenly: angle weighting still gives the diagonal
        String cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
            + "f 1 4 3\nf 1 3 2\n"          // z = 0, two triangles at vertex 1
            + "f 1 2 6\nf 1 6 5\n"          // y = 0, two triangles at vertex 1
            + "f 1 5 8\nf 1 8 4\n"          // x = 0, two triangles at vertex 1
            + "f 7 6 2\nf 7 2 3\nf 7 3 4\nf 7 4 8\nf 7 8 5\nf 7 5 6\n";
        Mesh mesh = ObjLoader.load(write("cube.obj", cube), true).mesh();
        float[] n = mesh.normals();
        double s = -1 / Math.sqrt(3);
        assertEquals(s, n[0], 1e-6);
        assertEquals(s, n[1], 1e-6);
        assertEquals(s, n[2], 1e-6);
        float[] flat = ObjLoader.load(write("quad.obj", SQUARE + "f 1 2 3 4\n"), true).mesh().normals();
        for (int v = 0; v < 4; v++) {
            assertEquals(1f, flat[3 * v + 2], 1e-6);
        }
    }

    // ---- real files from assets/ ----

    @Test
    void cornellBoxQuadsNegativeIndicesAndMaterials() throws ObjException {
        ObjModel m = ObjLoader.load(TestAssets.path("obj-parser/cornell_box/cornell_box.obj"), false);
        assertEquals(36, m.mesh().triangleCount(), "18 quads");
        assertTrue(m.materials().stream().anyMatch(x -> x.name().equals("light")), m.materials().toString());
        assertNotNull(m.mesh().materialIds());
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
    }

    @Test
    void spotQuadsWithUvsAndATexture() throws ObjException {
        ObjModel m = ObjLoader.load(TestAssets.path("spot/spot_quadrangulated.obj"), false);
        assertEquals(5856, m.mesh().triangleCount(), "2,928 quads");
        assertTrue(m.mesh().hasUvs());
        assertNotNull(m.materials().get(0).mapKd());
        assertTrue(Files.isRegularFile(m.materials().get(0).mapKd()));
    }

    @Test
    void blenderExportWithAMissingBumpMap() throws ObjException {
        ObjModel m = ObjLoader.load(TestAssets.path("obj-parser/blender_map_bump/map-bump.obj.gz"), false);
        assertEquals(400, m.mesh().triangleCount());
        assertTrue(m.mesh().hasNormals() && m.mesh().hasUvs());
        assertTrue(m.warnings().stream().anyMatch(w -> w.contains("bump.jpg")), m.warnings().toString());
    }

    @Test
    void stanfordBunnyAndDragon() throws ObjException {
        Mesh bunny = ObjLoader.load(TestAssets.path("meshes/stanford-bunny.obj.gz"), false).mesh();
        assertEquals(69_451, bunny.triangleCount());
        assertEquals(35_947, bunny.vertexCount());
        Mesh dragon = ObjLoader.load(TestAssets.path("meshes/stanford-dragon.obj.gz"), false).mesh();
        assertEquals(871_414, dragon.triangleCount());
        assertEquals(437_645, dragon.vertexCount());
        assertEquals(-0.108324, dragon.bounds().x0(), 1e-6);
        assertEquals(0.197173, dragon.bounds().y1(), 1e-6);
    }
}

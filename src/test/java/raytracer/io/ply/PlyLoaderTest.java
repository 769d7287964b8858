package raytracer.io.ply;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.TestAssets;
import raytracer.shapes.mesh.Mesh;

/**
 * PLY as the Stanford repository and other tools write it: ASCII and binary of both byte orders,
 * quads fan-triangulated, normals and texture coordinates kept, colours, other properties and
 * elements read past; the bunny as binary PLY is the bunny of the OBJ file. And a hostile set, as
 * for the OBJ loader: every malformed header or body is one error naming the file and the header
 * line or the element and its number, and an overstated count costs no memory before its data.
 */
class PlyLoaderTest {
    @TempDir
    Path dir;

    @Test
    void anAsciiCubeOfQuadsWithNormalsAndTextureCoordinates() throws Exception {
        PlyModel cube = PlyLoader.load(TestAssets.path("ply/cube-ascii.ply"), false);
        Mesh m = cube.mesh();
        assertEquals(8, m.vertexCount());
        assertEquals(12, m.triangleCount(), "six quads, two triangles each");
        assertEquals(6, cube.faces());
        assertEquals(6, cube.ngons());
        assertArrayEquals(new int[] {0, 2, 3, 0, 3, 1}, java.util.Arrays.copyOf(m.triangles(), 6), "the first quad fanned from its first corner");
        assertTrue(m.hasNormals() && m.hasUvs());
        assertEquals(1.0 / Math.sqrt(3), m.normals()[21], 1e-6, "vertex 7's normal (1, 1, 1) / sqrt 3");
        assertEquals(1, m.uvs()[2], "vertex 1: s = x = 1");
        assertEquals(1, cube.warnings().size());
        String warning = cube.warnings().get(0);
        for (String past : new String[] {"'red'", "'confidence'", "'flags'", "element 'edge'"}) {
            assertTrue(warning.contains(past), warning);
        }
    }

    @Test
    void binaryBigEndianGivesTheAsciiFilesMesh() throws Exception {
        Mesh ascii = PlyLoader.load(TestAssets.path("ply/cube-ascii.ply"), false).mesh();
        Mesh binary = PlyLoader.load(TestAssets.path("ply/cube-binary-be.ply"), false).mesh();
        assertArrayEquals(ascii.positions(), binary.positions());
        assertArrayEquals(ascii.normals(), binary.normals());
        assertArrayEquals(ascii.uvs(), binary.uvs());
        assertArrayEquals(ascii.triangles(), binary.triangles());
    }

    /** The bunny as binary little-endian PLY (float coordinates) is the OBJ file's bunny: same triangles, positions to float precision. */
    @Test
    void theBunnyAsPlyIsTheBunnyAsObj() throws Exception {
        Mesh ply = PlyLoader.load(TestAssets.path("ply/stanford-bunny.ply.gz"), false).mesh();
        Mesh obj = ObjLoader.load(TestAssets.path("meshes/stanford-bunny.obj.gz"), false).mesh();
        assertEquals(69_451, ply.triangleCount());
        assertArrayEquals(obj.triangles(), ply.triangles());
        double[] a = obj.positions();
        double[] b = ply.positions();
        assertEquals(a.length, b.length);
        for (int i = 0; i < a.length; i++) {
            assertEquals((float) a[i], b[i], 0.0, "coordinate " + i);
        }
        assertTrue(PlyLoader.load(TestAssets.path("ply/stanford-bunny.ply.gz"), true).mesh().hasNormals(), "smooth: normals made");
    }

    @Test
    void facesMayComeBeforeVerticesAndIndicesMayBeAnyIntegerType() throws Exception {
        Path file = write("order.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list ushort uint vertex_index\n"
                                       + "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n"
                                       + "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n");
        Mesh m = PlyLoader.load(file, false).mesh();
        assertEquals(1, m.triangleCount());
        assertEquals(1.0, m.positions()[3]);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        empty                    | ''                                                                                  | the file is empty
        not ply                  | 'v 0 0 0\\n'                                                                        | not a PLY file
        no end_header            | 'ply\\nformat ascii 1.0\\nelement vertex 1\\n'                                      | without 'end_header'
        no format                | 'ply\\nelement vertex 0\\nend_header\\n'                                            | no 'format' line
        unknown format           | 'ply\\nformat binary 1.0\\nend_header\\n'                                           | header line 2: unknown format 'binary'
        negative count           | 'ply\\nformat ascii 1.0\\nelement vertex -1\\nend_header\\n'                        | header line 3: element 'vertex' needs a count
        huge count               | 'ply\\nformat ascii 1.0\\nelement vertex 3000000000\\nend_header\\n'                | needs a count from 0 to 2147483647
        unknown type             | 'ply\\nformat ascii 1.0\\nelement vertex 1\\nproperty flaot x\\nend_header\\n'      | header line 4: unknown property type 'flaot'
        property first           | 'ply\\nformat ascii 1.0\\nproperty float x\\nend_header\\n'                          | header line 3: a property before any element
        unknown keyword          | 'ply\\nformat ascii 1.0\\nelemnt vertex 1\\nend_header\\n'                          | no 'vertex' element (skipped: header line 3: unknown keyword 'elemnt')
        real list count          | 'ply\\nformat ascii 1.0\\nelement face 1\\nproperty list float int vertex_indices\\nend_header\\n' | a list's count must be of an integer type
        no vertex element        | 'ply\\nformat ascii 1.0\\nelement face 0\\nproperty list uchar int vertex_indices\\nend_header\\n'  | no 'vertex' element
        no z                     | 'ply\\nformat ascii 1.0\\nelement vertex 1\\nproperty float x\\nproperty float y\\nend_header\\n0 0\\n' | needs scalar properties x, y and z
        no faces                 | 'ply\\nformat ascii 1.0\\nelement vertex 1\\nproperty float x\\nproperty float y\\nproperty float z\\nend_header\\n0 0 0\\n' | no faces
        no index list            | 'ply\\nformat ascii 1.0\\nelement vertex 0\\nproperty float x\\nproperty float y\\nproperty float z\\nelement face 0\\nproperty int a\\nend_header\\n' | needs a list property vertex_indices
        two corners              | 'HEADER2 0 1\\n'                                                                    | no faces (a PLY mesh needs a 'face' element with vertex_indices; its 1 face has fewer than 3 corners)
        too many corners         | 'ply\\nformat ascii 1.0\\nelement vertex 3\\nproperty float x\\nproperty float y\\nproperty float z\\nelement face 1\\nproperty list uint int vertex_indices\\nend_header\\n0 0 0\\n1 0 0\\n0 1 0\\n65537 0 1\\n' | :13: face 0 (of 1, counting from 0): a face of 65537 corners; at most 65536 are read
        negative list count      | 'ply\\nformat ascii 1.0\\nelement vertex 3\\nproperty float x\\nproperty float y\\nproperty float z\\nelement face 1\\nproperty list int8 int vertex_indices\\nend_header\\n0 0 0\\n1 0 0\\n0 1 0\\n-1 0 1\\n' | :13: face 0 (of 1, counting from 0): a list of -1 vertices
        index out of range       | 'HEADER3 0 1 3\\n'                                                                  | face 0 (of 1, counting from 0): vertex index 3 is out of range (the file has 3 vertices)
        negative index           | 'HEADER3 0 -1 2\\n'                                                                 | vertex index -1 is out of range
        two face elements        | 'ply\\nformat ascii 1.0\\nelement vertex 3\\nproperty float x\\nproperty float y\\nproperty float z\\nelement face 1\\nproperty list uchar int vertex_indices\\nelement face 1\\nproperty list uchar int vertex_indices\\nend_header\\n0 0 0\\n1 0 0\\n0 1 0\\n3 0 1 2\\n3 0 2 1\\n' | a second 'face' element
        truncated face           | 'HEADER3 0 1\\n'                                                                    | face 0 (of 1, counting from 0): the file ends early (truncated)
        not a number             | 'ply\\nformat ascii 1.0\\nelement vertex 1\\nproperty float x\\nproperty float y\\nproperty float z\\nend_header\\n0 zero 0\\n' | vertex 0 (of 1, counting from 0): property 'y': 'zero' is not a number
        not finite               | 'ply\\nformat ascii 1.0\\nelement vertex 1\\nproperty float x\\nproperty float y\\nproperty float z\\nend_header\\n0 NaN 0\\n' | vertex 0 (of 1, counting from 0): property 'y': its position is not finite
        beyond a triangle        | 'ply\\nformat ascii 1.0\\nelement vertex 1\\nproperty float x\\nproperty double y\\nproperty float z\\nend_header\\n0 1e80 0\\n' | vertex 0 (of 1, counting from 0): property 'y': its position coordinate 1.0E80 is beyond 1.0E75
        real index               | 'HEADER3 0 1 2.5\\n'                                                                | is not an integer
        overstated count         | 'ply\\nformat binary_little_endian 1.0\\nelement vertex 700000000\\nproperty float x\\nproperty float y\\nproperty float z\\nend_header\\n' | vertex 0 (of 700000000, counting from 0): the file ends early
        """)
    void malformedFilesAreOneErrorNamingTheFileAndWhere(String what, String text, String expected) throws Exception {
        String body = text.replace("HEADER", "ply\\nformat ascii 1.0\\nelement vertex 3\\nproperty float x\\nproperty float y\\n"
                                             + "property float z\\nelement face 1\\nproperty list uchar int vertex_indices\\nend_header\\n"
                                             + "0 0 0\\n1 0 0\\n0 1 0\\n").replace("\\n", "\n");
        Path file = write(what.replace(' ', '-') + ".ply", body);
        PlyException e = assertThrows(PlyException.class, () -> PlyLoader.load(file, false));
        assertTrue(e.getMessage().contains(expected), e.getMessage());
        assertTrue(e.getMessage().contains(file.toString()), "names the file: " + e.getMessage());
        assertTrue(!e.getMessage().contains("\n"), "one line: " + e.getMessage());
    }

    @Test
    void truncatedBinaryBodiesNameTheElement() throws Exception {
        String header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                        + "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
        ByteBuffer b = ByteBuffer.allocate(36 + 13 + 5).order(ByteOrder.LITTLE_ENDIAN);
        for (float v : new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}) {
            b.putFloat(v);
        }
        b.put((byte) 3).putInt(0).putInt(1).putInt(2);
        b.put((byte) 3).putInt(0); // the second face stops after one index
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(header.getBytes(StandardCharsets.US_ASCII));
        out.write(b.array(), 0, b.position());
        Path file = dir.resolve("truncated.ply");
        Files.write(file, out.toByteArray());
        PlyException e = assertThrows(PlyException.class, () -> PlyLoader.load(file, false));
        assertTrue(e.getMessage().endsWith("face 1 (of 2, counting from 0): the file ends early (truncated)"), e.getMessage());
        Path cut = dir.resolve("cut-vertices.ply");
        Files.write(cut, java.util.Arrays.copyOf(out.toByteArray(), header.length() + 20));
        e = assertThrows(PlyException.class, () -> PlyLoader.load(cut, false));
        assertTrue(e.getMessage().contains("vertex 1 (of 3, counting from 0): the file ends early"), e.getMessage());
    }

    @Test
    void compressedFilesAndTheirDamage() throws Exception {
        byte[] text = Files.readAllBytes(TestAssets.path("ply/cube-ascii.ply"));
        Path gz = dir.resolve("cube.ply.gz");
        ByteArrayOutputStream zipped = new ByteArrayOutputStream();
        try (GZIPOutputStream z = new GZIPOutputStream(zipped)) {
            z.write(text);
        }
        Files.write(gz, zipped.toByteArray());
        assertEquals(12, PlyLoader.load(gz, false).mesh().triangleCount());
        Path cut = dir.resolve("cut.ply.gz");
        Files.write(cut, java.util.Arrays.copyOf(zipped.toByteArray(), zipped.size() / 2));
        PlyException e = assertThrows(PlyException.class, () -> PlyLoader.load(cut, false));
        assertTrue(e.getMessage().contains(cut.toString()), e.getMessage());
    }

    @Test
    void aFolderOrAMissingFileIsRefusedByName() throws Exception {
        PlyException folder = assertThrows(PlyException.class, () -> PlyLoader.load(dir, false));
        assertTrue(folder.getMessage().endsWith("not a regular file"), folder.getMessage());
        PlyException missing = assertThrows(PlyException.class, () -> PlyLoader.load(dir.resolve("nothing.ply"), false));
        assertTrue(missing.getMessage().endsWith("no such file"), missing.getMessage());
    }

    @Test
    void anEndlessHeaderStopsAtItsLimit() throws Exception {
        Path file = dir.resolve("endless.ply");
        StringBuilder s = new StringBuilder("ply\nformat ascii 1.0\n");
        while (s.length() <= PlyHeader.MAX_BYTES) {
            s.append("comment ").append("x".repeat(100)).append('\n');
        }
        Files.writeString(file, s);
        PlyException e = assertThrows(PlyException.class, () -> PlyLoader.load(file, false));
        assertNotNull(e.getMessage());
        assertTrue(e.getMessage().contains("no 'end_header' in the first 1024 KiB"), e.getMessage());
    }

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, text.getBytes(StandardCharsets.ISO_8859_1));
        return file;
    }
}

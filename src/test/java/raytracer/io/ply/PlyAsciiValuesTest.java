package raytracer.io.ply;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.shapes.mesh.Mesh;

/**
 * Values of a PLY body as their declared types hold them. A number is read whole (the ASCII
 * reader kept the first 64 characters: 0.5 followed by 70 zeros and e1 read as 0.5); an integer
 * property takes an integer that fits its type, as rply and plyfile require (a uchar list count
 * of 300 was taken); a float property is read as the float it declares, as plyfile, trimesh and a
 * binary file read it; normals and texture coordinates fit the floats they are kept in (a double
 * normal of 1e300 became an infinite float and the mesh rendered black). ASCII errors name the
 * file and line.
 */
class PlyAsciiValuesTest {
    private static final String TRIANGLE = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                           + "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

    private static final String AFTER_THREE_VERTICES = "; the header's 3 'vertex' elements end here: if the body has more, "
                                                       + "the header declares too few";

    @TempDir
    Path dir;

    @Test
    void numbersAreReadWholeWhateverTheirLength() throws Exception {
        String zeros = "0".repeat(70);
        Path file = PlyFiles.text(dir, "long.ply", TRIANGLE + "0.5" + zeros + "e1 0 0\n1 0 0\n0 1 0\n3 0 1 " + zeros + "2\n");
        Mesh m = PlyLoader.load(file, false).mesh();
        assertEquals(5.0, m.positions()[0], "0.5e1");
        assertArrayEquals(new int[] {0, 1, 2}, m.triangles(), "index 2 after 70 zeros");
    }

    @Test
    void aWordLongerThanAnyNumberIsRefusedWithItsLine() throws Exception {
        Path file = PlyFiles.text(dir, "word.ply", TRIANGLE + "0 0 0\n1 0 0\n0 " + "1".repeat(5000) + " 0\n3 0 1 2\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(file, false)).getMessage();
        assertEquals(file + ":12: vertex 2 (of 3, counting from 0): property 'y': a word of more than "
                     + AsciiInput.MAX_WORD + " characters is not a number", message);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        uchar list count of 300 | property uchar flag         | 0             | 300 0 1 2                 | 'vertex_indices': '300' does not fit its type uchar (0 to 255)
        char of -200            | property char flag          | -200          | 3 0 1 2                   | 'flag': '-200' does not fit its type char (-128 to 127)
        short of 40000          | property short flag         | 40000         | 3 0 1 2                   | 'flag': '40000' does not fit its type short (-32768 to 32767)
        ushort of -1            | property uint16 flag        | -1            | 3 0 1 2                   | 'flag': '-1' does not fit its type ushort (0 to 65535)
        uint of 2^32            | property uint flag          | 4294967296    | 3 0 1 2                   | 'flag': '4294967296' does not fit its type uint (0 to 4294967295)
        int given 1.5           | property int32 flag         | 1.5           | 3 0 1 2                   | 'flag': '1.5' is not an integer (its type is int)
        index beyond int        | property uchar flag         | 0             | 3 0 1 3000000000          | 'vertex_indices': '3000000000' does not fit its type int (-2147483648 to 2147483647)
        integer beyond long     | property int flag           | 99999999999999999999 | 3 0 1 2            | 'flag': '99999999999999999999' does not fit its type int (-2147483648 to 2147483647)
        float beyond a float    | property float flag         | 0             | 3 0 1 2                   | SEE_X
        """)
    void aValueMustFitItsDeclaredType(String what, String property, String flag, String face, String expected) throws Exception {
        String header = TRIANGLE.replace("property float z\n", "property float z\n" + property + "\n");
        String x = expected.equals("SEE_X") ? "1e39" : "0";
        Path file = PlyFiles.text(dir, what.replace(' ', '-') + ".ply",
                                  header + x + " 0 0 " + flag + "\n1 0 0 0\n0 1 0 0\n" + face + "\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(file, false)).getMessage();
        String at = expected.startsWith("'vertex_indices'") ? ":14: face 0 (of 1, counting from 0): property "
                                                             : ":11: vertex 0 (of 3, counting from 0): property ";
        String whole = expected.equals("SEE_X") ? "'x': '1e39' does not fit its type float (at most 3.40282e+38 in size)" : expected;
        // an error in the first face says where the vertices ended, as the header may declare too few
        String after = expected.startsWith("'vertex_indices'") ? AFTER_THREE_VERTICES : "";
        assertEquals(file + at + whole + after, message);
    }

    @Test
    void aFloatPropertyIsReadAsTheFloatItDeclares() throws Exception {
        String header = TRIANGLE.replace("property float y", "property double y");
        Path file = PlyFiles.text(dir, "floats.ply", header + "-1023.32 -1023.32 0.1\n1 0 0\n0 1 0\n3 0 1 2\n");
        double[] p = PlyLoader.load(file, false).mesh().positions();
        assertEquals((float) -1023.32, p[0], 0.0, "float x, as plyfile and trimesh read it (-1023.3200073242188)");
        assertEquals(-1023.32, p[1], 0.0, "double y");
        assertEquals((float) 0.1, p[2], 0.0);
    }

    /**
     * A float read past may be out of a float's range, or not finite: plyfile, trimesh and tinyply
     * all read 1e39, -1e400, inf and nan in a float property and go on (rply refuses them).
     */
    @Test
    void aPropertyReadPastOnlyNeedsToBeANumber() throws Exception {
        String header = TRIANGLE.replace("property float z\n", "property float z\nproperty float quality\n");
        Path file = PlyFiles.text(dir, "quality.ply", header + "0 0 0 1e39\n1 0 0 -1e400\n0 1 0 -INF\n3 0 1 2\n");
        assertEquals(1, PlyLoader.load(file, false).mesh().triangleCount());
        Path nan = PlyFiles.text(dir, "nan.ply", header + "0 0 0 nan\n1 0 0 Infinity\n0 1 0 +inf\n3 0 1 2\n");
        assertEquals(1, PlyLoader.load(nan, false).mesh().triangleCount());
        Path used = PlyFiles.text(dir, "used.ply", header + "0 0 0 0\n1 inf 0 0\n0 1 0 0\n3 0 1 2\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(used, false)).getMessage();
        assertEquals(used + ":12: vertex 1 (of 3, counting from 0): property 'y': its position is not finite (Infinity)", message);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        normal       | nx ny nz | 0 1e300 0 | 'ny': normal component 1.0E300 is beyond the largest float (3.40282e+38)
        texture u    | u v      | -1e39 0   | 'u': texture coordinate -1.0E39 is beyond the largest float (3.40282e+38)
        texture t    | s t      | 0 4e38    | 't': texture coordinate 4.0E38 is beyond the largest float (3.40282e+38)
        """)
    void normalsAndTextureCoordinatesMustFitAFloat(String what, String names, String values, String expected) throws Exception {
        StringBuilder properties = new StringBuilder();
        for (String name : names.split(" ")) {
            properties.append("property double ").append(name).append('\n');
        }
        String header = TRIANGLE.replace("property float z\n", "property float z\n" + properties);
        String zeros = values.replaceAll("[^ ]+", "0");
        Path ascii = PlyFiles.text(dir, what.replace(' ', '-') + ".ply",
                                   header + "0 0 0 " + zeros + "\n1 0 0 " + values + "\n0 1 0 " + zeros + "\n3 0 1 2\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(ascii, false)).getMessage();
        assertEquals(ascii + ":" + (11 + names.split(" ").length) + ": vertex 1 (of 3, counting from 0): property " + expected, message);

        String[] v = values.split(" ");
        Path binary = PlyFiles.binary(dir, what.replace(' ', '-') + ".bin.ply", header.replace("ascii", "binary_little_endian"),
                                      ByteOrder.LITTLE_ENDIAN, b -> {
                for (int i = 0; i < 3; i++) {
                    b.putFloat(i == 1 ? 1 : 0).putFloat(i == 2 ? 1 : 0).putFloat(0);
                    for (String value : v) {
                        b.putDouble(i == 1 ? Double.parseDouble(value) : 0);
                    }
                }
                b.put((byte) 3).putInt(0).putInt(1).putInt(2);
            });
        message = assertThrows(PlyException.class, () -> PlyLoader.load(binary, false)).getMessage();
        assertEquals(binary + ": vertex 1 (of 3, counting from 0): property " + expected, message);
    }

    /** The vertex count of the header is 2, the body has 3: the third vertex is read where the face begins. */
    @Test
    void aHeaderThatDeclaresFewerVerticesThanTheBodyHasIsSaidSo() throws Exception {
        String header = TRIANGLE.replace("element vertex 3", "element vertex 2");
        Path file = PlyFiles.text(dir, "fewer.ply", header + "0 0 0\n1 0 0\n-1 1 0\n3 0 1 2\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(file, false)).getMessage();
        assertEquals(file + ":12: face 0 (of 1, counting from 0): property 'vertex_indices': '-1' does not fit its type uchar "
                     + "(0 to 255); the header's 2 'vertex' elements end here: if the body has more, the header declares too few",
                     message);
        assertFalse(message.contains("got -1"), message);

        Path real = PlyFiles.text(dir, "fewer-real.ply", header + "0 0 0\n1 0 0\n0.5 1 0\n3 0 1 2\n");
        message = assertThrows(PlyException.class, () -> PlyLoader.load(real, false)).getMessage();
        assertTrue(message.startsWith(real + ":12: face 0 (of 1, counting from 0): property 'vertex_indices': '0.5' is not an integer"),
                   message);
        assertTrue(message.endsWith("the header declares too few"), message);
    }

    /** plyfile and trimesh read the faces the header declares and no more; the rest is named in a warning. */
    @Test
    void moreDataThanTheHeaderDeclaresIsAWarning() throws Exception {
        Path file = PlyFiles.text(dir, "more.ply", TRIANGLE + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n3 0 2 1\n");
        PlyModel model = PlyLoader.load(file, false);
        assertEquals(1, model.mesh().triangleCount());
        assertEquals(List.of(file + ":15: the body goes on after the last element the header declares ('face'); "
                             + "the rest is not read"), model.warnings());
    }
}

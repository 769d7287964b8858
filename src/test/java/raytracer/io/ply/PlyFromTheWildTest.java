package raytracer.io.ply;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.shapes.mesh.Mesh;

/**
 * PLY files of the shapes exporters and other loaders' test data have, each written small here,
 * read as plyfile 1.1, trimesh 5.2 and tinyply 2.3 read them: the same triangles (faces of more than
 * three corners fanned from their first, as trimesh does) and coordinates. What the three read,
 * this loader reads; what it refuses, at least one of them refuses too.
 */
class PlyFromTheWildTest {
    private static final String XYZ = "property float x\nproperty float y\nproperty float z\n";

    @TempDir
    Path dir;

    private Mesh load(Path file) throws PlyException {
        return PlyLoader.load(file, false).mesh();
    }

    private static void assertVertex(Mesh m, int v, double x, double y, double z) {
        assertArrayEquals(new double[] {x, y, z}, java.util.Arrays.copyOfRange(m.positions(), 3 * v, 3 * v + 3), "vertex " + v);
    }

    /**
     * Blender 2.47's exporter wrote its banner as a header line of its own, without 'comment'.
     * trimesh reads past any line it does not know and tinyply reports it and reads on; plyfile
     * refuses it, and obj_info after an element too. A warning names the first such line.
     */
    @Test
    void headerLinesOfFreeTextAreSkippedWithAWarning() throws Exception {
        Path file = PlyFiles.text(dir, "banner.ply", "ply\nformat ascii 1.0\nWritten by a modeller 2.4 - free text, source file: \n"
            + "obj_info scanner 3\nelement vertex 4\n" + XYZ + "exporter notes\nproperty float nx\nproperty float ny\nproperty float nz\n"
            + "property float s\nproperty float t\nobj_info after the vertex element\nelement face 2\n"
            + "property list uchar uint vertex_indices\nend_header\n"
            + "0.5 0 0 0 0 1 0 0 \n1 0 0 0 0 1 1 0 \n1 1 0 0 0 1 1 1 \n0 1 0 0 0 1 0 1 \n3 0 1 2 \n3 0 2 3 \n");
        PlyModel model = PlyLoader.load(file, false);
        Mesh m = model.mesh();
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.triangles());
        assertVertex(m, 0, 0.5, 0, 0);
        assertTrue(m.hasNormals() && m.hasUvs());
        assertEquals(List.of(file + ": header line 3: unknown keyword 'Written', line skipped (2 such lines)"), model.warnings());
    }

    /** tinyply reads blank header lines, plyfile and trimesh refuse them; all three read tabs, runs of spaces and CRLF. */
    @Test
    void tabsSpacesBlankLinesAndCrlfInHeaderAndBody() throws Exception {
        Path file = PlyFiles.text(dir, "spaces.ply", "ply\r\nformat  ascii\t1.0 \r\n\r\ncomment  spaced\r\nelement\tvertex  4 \r\n"
            + "property float\tx\r\nproperty  float y \r\nproperty float   z\r\n\r\nelement face 2\r\n"
            + "property list  uchar int\tvertex_indices\r\nend_header\r\n"
            + "  0 0 0 \r\n1\t0\t0\r\n\r\n1  1  0\t\r\n 0 1 0\r\n3 0 1 2 \r\n\t3 0 2 3\r\n\r\n");
        Mesh m = load(file);
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.triangles());
        assertVertex(m, 2, 1, 1, 0);
    }

    /** plyfile reads comments anywhere, before the format line too; trimesh takes the second line for the format. */
    @Test
    void commentsAnywhereInTheHeader() throws Exception {
        Path file = PlyFiles.text(dir, "comments.ply", "ply\ncomment before format\nformat ascii 1.0\ncomment\nelement vertex 3\n"
            + "comment between element and property\nproperty float x\ncomment between properties\nproperty float y\n"
            + "property float z\nelement face 1\ncomment in face\nproperty list uchar int vertex_indices\ncomment before end\n"
            + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        assertEquals(1, load(file).triangleCount());
    }

    /** Colours as floats (VCG writes them so) are read past as any other property; the file ends without a line break. */
    @Test
    void floatVertexColoursAndNoFinalLineBreak() throws Exception {
        Path file = PlyFiles.text(dir, "float-colours.ply", "ply\nformat ascii 1.0\ncomment colours as floats\nelement vertex 3\n"
            + XYZ + "property float red\nproperty float green\nproperty float blue\nproperty float alpha\n"
            + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
            + "0.0 0.0 0.0 1 0 0 1\n10.0 0.0 0.0 0 1 0 1\n20.0 20.0 0.0 0 0 1 0.5\n3 0 1 2");
        PlyModel model = PlyLoader.load(file, false);
        assertVertex(model.mesh(), 2, 20, 20, 0);
        assertEquals(1, model.mesh().triangleCount());
        assertEquals(1, model.warnings().size());
        assertTrue(model.warnings().get(0).contains("vertex property 'alpha'"), model.warnings().get(0));
    }

    /** Every type name of the 1994 paper and of the sized set, in coordinates, list counts and list items (plyfile, trimesh). */
    @Test
    void everyTypeNameInAnyPropertyAscii() throws Exception {
        Path file = PlyFiles.text(dir, "types.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float32 x\nproperty float64 y\n"
            + "property int16 z\nproperty uint8 flags\nproperty list int8 float64 weights\nproperty uint16 id\nproperty int32 a\n"
            + "property uint32 b\nproperty char c\nproperty uchar d\nproperty short e\nproperty ushort f\nproperty int g\n"
            + "property uint h\nproperty float i\nproperty double j\nelement face 1\nproperty list int8 uint16 vertex_indices\n"
            + "end_header\n"
            + "0.25 0 -3 7 2 0.5 1e300 1 -5 6 -128 255 -32768 65535 -2147483648 4294967295 1.5 2.5\n"
            + "4 0 -3 7 0 2 -5 6 127 0 32767 0 2147483647 0 0 0\n"
            + "0 5 -3 7 1 -2 3 -5 6 0 0 0 0 0 0 0 0\n3 0 1 2\n");
        Mesh m = load(file);
        assertArrayEquals(new int[] {0, 1, 2}, m.triangles());
        assertVertex(m, 0, 0.25, 0, -3);
        assertVertex(m, 2, 0, 5, -3);
    }

    /** The same in binary big-endian: each type takes its own size, and an int8 count and a float64 list are read past. */
    @Test
    void everyTypeNameInAnyPropertyBinary() throws Exception {
        String[] names = {"char", "int8", "uchar", "uint8", "short", "int16", "ushort", "uint16", "int", "int32", "uint", "uint32",
                          "float", "float32", "double", "float64"};
        int[] sizes = {1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8};
        StringBuilder header = new StringBuilder("ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty int16 x\n"
                                                 + "property float64 y\nproperty uint8 z\n");
        for (int k = 0; k < names.length; k++) {
            header.append("property ").append(names[k]).append(" p").append(k).append('\n');
        }
        header.append("element face 1\nproperty list int8 uint32 vertex_indices\nproperty list uint16 float64 weights\nend_header\n");
        double[][] xyz = {{-2, 0.5, 7}, {3, 0.25, 0}, {0, -1.5, 255}};
        Path file = PlyFiles.binary(dir, "types-be.ply", header.toString(), ByteOrder.BIG_ENDIAN, b -> {
            for (double[] v : xyz) {
                b.putShort((short) v[0]).putDouble(v[1]).put((byte) v[2]);
                for (int k = 0; k < names.length; k++) {
                    switch (sizes[k]) {
                        case 1 -> b.put((byte) -1);
                        case 2 -> b.putShort((short) -1);
                        case 4 -> b.putInt(names[k].startsWith("float") ? Float.floatToIntBits(1) : -1);
                        default -> b.putDouble(1);
                    }
                }
            }
            b.put((byte) 3).putInt(0).putInt(1).putInt(2).putShort((short) 2).putDouble(0.5).putDouble(0.5);
        });
        Mesh m = load(file);
        assertArrayEquals(new int[] {0, 1, 2}, m.triangles());
        assertVertex(m, 0, -2, 0.5, 7);
        assertVertex(m, 2, 0, -1.5, 255);
    }

    /** Colours per face after the index list (plyfile's tet.ply has them so), in ASCII and binary. */
    @Test
    void faceColoursAfterTheIndexList() throws Exception {
        String header = "element face 2\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
                        + "property uchar blue\nend_header\n";
        Path ascii = PlyFiles.text(dir, "face-colours.ply", "ply\nformat ascii 1.0\nelement vertex 4\n" + XYZ + header
                                                            + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 255 0 0\n3 0 2 3 0 255 0\n");
        Path binary = PlyFiles.binary(dir, "face-colours-le.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4\n" + XYZ
                                                                  + header, ByteOrder.LITTLE_ENDIAN, b -> {
                for (float[] v : new float[][] {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) {
                    b.putFloat(v[0]).putFloat(v[1]).putFloat(v[2]);
                }
                b.put((byte) 3).putInt(0).putInt(1).putInt(2).put((byte) 255).put((byte) 0).put((byte) 0);
                b.put((byte) 3).putInt(0).putInt(2).putInt(3).put((byte) 0).put((byte) 255).put((byte) 0);
            });
        for (Path file : new Path[] {ascii, binary}) {
            PlyModel model = PlyLoader.load(file, false);
            assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, model.mesh().triangles(), file.toString());
            assertVertex(model.mesh(), 2, 1, 1, 0);
            assertTrue(model.warnings().get(0).contains("face property 'blue'"), model.warnings().toString());
        }
    }

    /** Coordinates as doubles, indices as shorts and ushorts (ply-rs's diverse field formats), both byte orders; a quad gives two triangles. */
    @Test
    void doubleCoordinatesAndShortIndices() throws Exception {
        for (ByteOrder order : new ByteOrder[] {ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN}) {
            for (String index : new String[] {"short", "ushort"}) {
                String format = order == ByteOrder.BIG_ENDIAN ? "binary_big_endian" : "binary_little_endian";
                String header = "ply\nformat " + format + " 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                + "property double z\nelement face 1\nproperty list uchar " + index + " vertex_indices\nend_header\n";
                Path file = PlyFiles.binary(dir, format + "-" + index + ".ply", header, order, b -> {
                    for (double[] v : new double[][] {{0.1, 0, 0}, {1, 0, 0}, {1, 1, 0.3}, {0, 1, 0}}) {
                        b.putDouble(v[0]).putDouble(v[1]).putDouble(v[2]);
                    }
                    b.put((byte) 4).putShort((short) 0).putShort((short) 1).putShort((short) 2).putShort((short) 3);
                });
                Mesh m = load(file);
                assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.triangles(), file.toString());
                assertVertex(m, 0, 0.1, 0, 0);
                assertVertex(m, 2, 1, 1, 0.3);
            }
        }
    }

    /** A uint list count, then the face's normal after the list: the values after a list are found by its count. */
    @Test
    void aUintCountThenNormalsInTheFaceElement() throws Exception {
        String header = "ply\nformat binary_little_endian 1.0\nelement vertex 4\n" + XYZ + "element face 2\n"
                        + "property list uint int vertex_indices\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n";
        Path file = PlyFiles.binary(dir, "uint-count.ply", header, ByteOrder.LITTLE_ENDIAN, b -> {
            for (float[] v : new float[][] {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) {
                b.putFloat(v[0]).putFloat(v[1]).putFloat(v[2]);
            }
            b.putInt(3).putInt(0).putInt(1).putInt(2).putFloat(0).putFloat(0).putFloat(1);
            b.putInt(3).putInt(0).putInt(2).putInt(3).putFloat(0).putFloat(0).putFloat(1);
        });
        Mesh m = load(file);
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.triangles());
        assertTrue(!m.hasNormals(), "a face's normal is not a vertex normal");
    }

    /** rply's sample: a comment after the last property, numbers with leading zeros, trailing spaces. */
    @Test
    void rplysSampleLayout() throws Exception {
        Path file = PlyFiles.text(dir, "rply-like.ply", "ply\nformat ascii 1.0\ncomment first\nelement vertex 3\n" + XYZ
            + "element face 2\nproperty list uchar int vertex_indices\ncomment last\nend_header\n"
            + "-2 0 0 \n000 2 0 \n2 0000 0\n3 1 00000 2\n3 1 0 2\n");
        Mesh m = load(file);
        assertArrayEquals(new int[] {1, 0, 2, 1, 0, 2}, m.triangles());
        assertVertex(m, 0, -2, 0, 0);
        assertVertex(m, 1, 0, 2, 0);
    }

    /**
     * Elements in another order with others around them, vertex_index for vertex_indices,
     * coordinates in another order, a face's properties before and after its list. tinyply asks
     * for properties in file order; plyfile and trimesh read it as here.
     */
    @Test
    void elementsAndPropertiesInAnyOrder() throws Exception {
        Path file = PlyFiles.text(dir, "order.ply", "ply\nformat ascii 1.0\nelement material 2\nproperty uchar red\n"
            + "property list uchar float params\nelement face 1\nproperty uchar flags\nproperty list uchar int vertex_index\n"
            + "property float quality\nelement vertex 3\nproperty float z\nproperty uchar confidence\nproperty float y\n"
            + "property float x\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
            + "1 2 0.5 0.25\n2 0\n7 3 2 1 0 0.5\n0 1 0 0\n0 2 1 0\n0 3 0 4\n0 1\n");
        Mesh m = load(file);
        assertArrayEquals(new int[] {2, 1, 0}, m.triangles());
        assertVertex(m, 1, 0, 1, 0);
        assertVertex(m, 2, 4, 0, 0);
    }

    /** Elements of no rows anywhere (a scanner's empty camera or material element). */
    @Test
    void elementsOfZeroCount() throws Exception {
        Path file = PlyFiles.text(dir, "zero.ply", "ply\nformat ascii 1.0\nelement camera 0\nproperty float view_px\nelement vertex 3\n"
            + XYZ + "element edge 0\nproperty int vertex1\nelement face 1\nproperty list uchar int vertex_indices\n"
            + "element material 0\nproperty uchar red\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        assertEquals(1, load(file).triangleCount());
    }

    /**
     * A face of fewer than three corners has no triangle: trimesh leaves it out (as tinyobjloader
     * does in OBJ), so it is skipped with one warning; a pentagon is fanned into three.
     */
    @Test
    void facesOfFewerThanThreeCornersAreSkipped() throws Exception {
        Path file = PlyFiles.text(dir, "degenerate.ply", "ply\nformat ascii 1.0\nelement vertex 5\n" + XYZ + "element face 5\n"
            + "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 1.5 0\n"
            + "3 0 1 2\n2 0 1\n1 3\n0\n5 0 1 2 4 3\n");
        PlyModel model = PlyLoader.load(file, false);
        assertArrayEquals(new int[] {0, 1, 2, 0, 1, 2, 0, 2, 4, 0, 4, 3}, model.mesh().triangles());
        assertEquals(List.of(file + ":16: face 1 (of 5, counting from 0): a face of 2 corners has no triangle "
                             + "(3 faces of fewer than 3 corners skipped)"), model.warnings());
        assertEquals(2, model.faces(), "faces read as faces");

        Path only = PlyFiles.text(dir, "only-degenerate.ply", "ply\nformat ascii 1.0\nelement vertex 2\n" + XYZ + "element face 1\n"
            + "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n2 0 1\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(only, false)).getMessage();
        assertEquals(only + ": no faces (a PLY mesh needs a 'face' element with vertex_indices; its 1 face has fewer than 3 corners)",
                     message);
    }

    /** Triangle strips are not faces: plyfile and trimesh read none from them either, so the error says what was read past. */
    @Test
    void aTristripsElementIsNoFaces() throws Exception {
        Path file = PlyFiles.text(dir, "strips.ply", "ply\nformat ascii 1.0\nelement vertex 4\n" + XYZ + "element tristrips 1\n"
            + "property list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2 3\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(file, false)).getMessage();
        assertEquals(file + ": no faces (a PLY mesh needs a 'face' element with vertex_indices; read past: element 'tristrips')",
                     message);
    }

    /** Index lists of a real type: plyfile and trimesh read whole numbers as indices, in ASCII and binary. */
    @Test
    void indexListsOfARealType() throws Exception {
        String header = "element vertex 3\n" + XYZ + "element face 1\nproperty list uchar double vertex_indices\nend_header\n";
        Path binary = PlyFiles.binary(dir, "real-indices.ply", "ply\nformat binary_little_endian 1.0\n" + header,
                                      ByteOrder.LITTLE_ENDIAN, b -> {
                for (int k = 0; k < 9; k++) {
                    b.putFloat(k == 3 || k == 7 ? 1 : 0);
                }
                b.put((byte) 3).putDouble(0).putDouble(1).putDouble(2);
            });
        assertArrayEquals(new int[] {0, 1, 2}, load(binary).triangles());
        Path ascii = PlyFiles.text(dir, "real-indices.ply", "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2.0\n");
        assertArrayEquals(new int[] {0, 1, 2}, load(ascii).triangles());
        Path half = PlyFiles.text(dir, "half.ply", "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n");
        String message = assertThrows(PlyException.class, () -> PlyLoader.load(half, false)).getMessage();
        assertTrue(message.startsWith(half + ":13: face 0 (of 1, counting from 0): property 'vertex_indices': vertex index 1.5 "
                                      + "is not a whole number"), message);
    }
}

package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.shapes.mesh.Mesh;

/** Faces as files from the wild write them: any corner count, empty index slots, attributes that do not exist. */
class ObjFacesTest {
    private static final String TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

    @TempDir
    Path dir;

    private ObjModel load(String text) throws IOException, ObjException {
        Path file = dir.resolve("m.obj");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return ObjLoader.load(file, false);
    }

    private String error(String text) throws IOException {
        Path file = dir.resolve("bad.obj");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return assertThrows(ObjException.class, () -> ObjLoader.load(file, false)).getMessage();
    }

    /** n vertices on the unit circle and one face through all of them, every corner written as {@code form}. */
    private static String polygon(int n, String form) {
        StringBuilder s = new StringBuilder();
        for (int k = 0; k < n; k++) {
            double a = 2 * Math.PI * k / n;
            s.append("v ").append(Math.cos(a)).append(' ').append(Math.sin(a)).append(" 0\nvt 0.5 0.5\nvn 0 0 1\n");
        }
        s.append('f');
        for (int k = 1; k <= n; k++) {
            s.append(' ').append(form.replace("K", Integer.toString(k)));
        }
        return s.append('\n').toString();
    }

    @Test
    void aFaceOfThousandsOfCornersIsFanTriangulated() throws Exception {
        // the fuzz finding: 3,000 repeated corners overflowed the stack of the face pattern
        Mesh repeated = load(TRIANGLE + "f 1 2 3" + " 1".repeat(3000) + "\n").mesh();
        assertEquals(3001, repeated.triangleCount());
        assertEquals(0, repeated.vertex(3000, 0));
        assertEquals(2, repeated.vertex(0, 2));
        // 2,000 full corners, and a 65-gon (refused as "more than 64 corners" before)
        for (int n : new int[] {65, 2000}) {
            ObjModel m = load(polygon(n, "K/K/K"));
            assertEquals(n - 2, m.mesh().triangleCount(), n + " corners");
            assertEquals(1, m.ngons(), "one face of more than 3 corners");
            // the fan (0, i, i + 1): the last triangle ends at the last corner, whose position is known
            int last = m.mesh().vertex(n - 3, 2);
            double a = 2 * Math.PI * (n - 1) / n;
            assertArrayEquals(new double[] {Math.cos(a), Math.sin(a), 0},
                              Arrays.copyOfRange(m.mesh().positions(), 3 * last, 3 * last + 3), 1e-15);
        }
    }

    @Test
    void thousandsOfContinuationsMakeOneFace() throws Exception {
        Mesh mesh = load(TRIANGLE + "f 1 2 3" + " \\\n1".repeat(3000) + "\nf 3 2 1\n").mesh();
        assertEquals(3002, mesh.triangleCount());
        assertEquals(2, mesh.vertex(3001, 0), "the face after the continued one starts at its own line");
    }

    @Test
    void emptyTrailingIndexSlotsAreAbsentAttributes() throws Exception {
        Mesh noSlots = load(TRIANGLE + "vt 0 0\nvt 1 0\nvt 0 1\nf 1// 2// 3//\n").mesh();
        assertEquals(1, noSlots.triangleCount());
        assertFalse(noSlots.hasUvs() || noSlots.hasNormals(), "'1//' names a position only");
        Mesh uvOnly = load(TRIANGLE + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/3/ 2/2/ 3/1/\n").mesh();
        assertTrue(uvOnly.hasUvs());
        assertFalse(uvOnly.hasNormals(), "'1/3/' names a position and a texture coordinate");
        int v = uvOnly.vertex(0, 0);
        assertArrayEquals(new float[] {0, 1}, Arrays.copyOfRange(uvOnly.uvs(), 2 * v, 2 * v + 2));
    }

    @Test
    void attributesThatDoNotExistAreDroppedWithOneWarning() throws Exception {
        // no vt line at all, then a normal index past the one normal
        ObjModel m = load(TRIANGLE + "v 1 1 0\nvn 0 0 1\nf 1/1 2/2 3/3\nf 2/1 4/2 3/3\nf 1//1 2//2 3//1\nf 2//1 4//1 3//1\n");
        assertEquals(4, m.mesh().triangleCount(), "the geometry is kept");
        assertFalse(m.mesh().hasUvs());
        assertTrue(m.mesh().hasNormals());
        int kept = m.mesh().vertex(3, 0);
        assertEquals(1f, m.mesh().normals()[3 * kept + 2], "the face whose normals exist keeps them");
        int dropped = m.mesh().vertex(2, 0);
        assertEquals(0f, m.mesh().normals()[3 * dropped + 2], "the face naming normal 2 has none (the face normal is used)");
        assertEquals(2, m.warnings().size(), m.warnings().toString());
        assertEquals(dir.resolve("m.obj") + ":6: texture coordinate index 1 does not exist (none defined so far); "
                     + "2 faces naming texture coordinates that do not exist are kept without them", m.warnings().get(0));
        assertEquals(dir.resolve("m.obj") + ":8: normal index 2 does not exist (1 defined so far); "
                     + "1 face naming normals that do not exist is kept without them", m.warnings().get(1));
    }

    /**
     * A face of fewer than three corners has no triangle: tinyobjloader skips it with a warning
     * ("Degenerated face found"), and so does this loader, once a file, with the count. Zero
     * corners ("f" alone) is the same case. A file of nothing else has no faces.
     */
    @Test
    void facesOfFewerThanThreeCornersAreSkippedWithOneWarning() throws Exception {
        ObjModel m = load(TRIANGLE + "f 1 2 3\nf 1 2\nf 3\nf # none\nf 3 2 1\n");
        assertArrayEquals(new int[] {0, 1, 2, 2, 1, 0}, m.mesh().triangles());
        assertEquals(2, m.faces());
        assertEquals(java.util.List.of(dir.resolve("m.obj") + ":5: a face of 2 corners has no triangle; "
                                       + "3 faces of fewer than 3 corners skipped"), m.warnings());
        ObjModel one = load(TRIANGLE + "f 1\nf 1 2 3\n");
        assertEquals(java.util.List.of(dir.resolve("m.obj") + ":4: a face of 1 corner has no triangle; "
                                       + "1 face of fewer than 3 corners skipped"), one.warnings());
        assertEquals(dir.resolve("bad.obj") + ": no faces (an OBJ mesh needs 'f' lines)", error(TRIANGLE + "f 1 2\nf 2 3\n"));
        assertEquals(error(TRIANGLE), error(TRIANGLE + "f 1 2\n"), "as a file without faces");
        // a corner that does not parse is still an error, whatever the count
        assertTrue(error(TRIANGLE + "f 1 x\n").contains(":4: expected 'f' and at least 3 corners"), error(TRIANGLE + "f 1 x\n"));
        assertTrue(error(TRIANGLE + "f 1 9\n").contains(":4: vertex index 9 is out of range"), error(TRIANGLE + "f 1 9\n"));
    }

    @Test
    void outOfRangeVerticesStillStopTheLoadWithTheIndexAsWritten() throws IOException {
        assertEquals(dir.resolve("bad.obj") + ":4: vertex index 99999999999 is out of range "
                     + "(3 defined so far; indices are 1..3 or -1..-3)", error(TRIANGLE + "f 1 2 99999999999\n"));
        assertEquals(dir.resolve("bad.obj") + ":1: vertex index -1 is out of range (no vertex is defined before this line)",
                     error("f -1 -2 -3\nv 0 0 0\n"));
        assertTrue(error(TRIANGLE + "f 1 2 3 1/ 2 x\n").contains(":4: expected 'f' and at least 3 corners"));
    }

    @Test
    void faceCountsForStatistics() throws Exception {
        ObjModel m = load(TRIANGLE + "v 1 1 0\nf 1 2 3\nf 1 2 4 3\nf 1 2 4 3\n");
        assertEquals(5, m.mesh().triangleCount());
        assertEquals(3, m.faces());
        assertEquals(2, m.ngons());
        assertNull(m.mesh().materialIds());
    }
}

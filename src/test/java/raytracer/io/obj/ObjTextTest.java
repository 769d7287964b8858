package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The text of an OBJ file as exporters write it: byte-order marks, Latin-1, old line ends, comments, foreign lines. */
class ObjTextTest {
    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    @TempDir
    Path dir;

    private Path write(String name, byte[] bytes) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, bytes);
        return file;
    }

    private Path write(String name, String text) throws IOException {
        return write(name, text.getBytes(StandardCharsets.UTF_8));
    }

    private static byte[] bom(String text) {
        byte[] body = text.getBytes(StandardCharsets.UTF_8);
        byte[] all = new byte[body.length + 3];
        all[0] = (byte) 0xEF;
        all[1] = (byte) 0xBB;
        all[2] = (byte) 0xBF;
        System.arraycopy(body, 0, all, 3, body.length);
        return all;
    }

    @Test
    void aByteOrderMarkIsNotPartOfTheFirstLine() throws Exception {
        write("lib.mtl", bom("newmtl red\nKd 1 0 0\n"));
        ObjModel m = ObjLoader.load(write("m.obj", bom(SQUARE + "mtllib lib.mtl\nusemtl red\nf 1 2 3\n")), false);
        assertArrayEquals(new double[] {0, 0, 0}, java.util.Arrays.copyOfRange(m.mesh().positions(), 0, 3), 0);
        assertEquals(0, m.mesh().vertex(0, 0), "the first vertex is read");
        assertArrayEquals(new double[] {1, 0, 0}, m.materials().get(0).kd(), 0, "the first newmtl is read");
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
    }

    @Test
    void latin1NamesMatchBetweenObjAndMtl() throws Exception {
        write("lib.mtl", "newmtl caf\u00e9\nKd 0 1 0\nnewmtl other\nKd 0 0 1\n".getBytes(StandardCharsets.ISO_8859_1));
        ObjModel m = ObjLoader.load(write("m.obj", (SQUARE + "mtllib lib.mtl\nusemtl caf\u00e9\nf 1 2 3\nusemtl other\nf 1 3 4\n")
            .getBytes(StandardCharsets.ISO_8859_1)), false);
        assertEquals("caf\u00e9", m.materials().get(0).name());
        assertArrayEquals(new double[] {0, 1, 0}, m.materials().get(0).kd(), 0);
        assertArrayEquals(new double[] {0, 0, 1}, m.materials().get(1).kd(), 0, "every material of the library is kept");
        assertEquals(List.of(dir.resolve("m.obj") + ":6: a byte that is not UTF-8; this part of the file is read as ISO-8859-1 (Latin-1)",
                             dir.resolve("lib.mtl") + ":1: a byte that is not UTF-8; the file is read as ISO-8859-1 (Latin-1)"),
                     m.warnings());
    }

    @Test
    void lineChunksCutOldMacLinesToo() throws IOException {
        // a file of '\r' line ends only was one chunk, parsed serially (and 40 times slower than '\n');
        // a cut never splits "\r\n" and never follows a continued line, whatever its line end
        for (String line : new String[] {"v 1 2 3\r", "v 1 2 3\r\n", "v 1 \\\r2 3\r", "v 1 \\\r\n2 3\r\n"}) {
            byte[] text = line.repeat(3 * LineChunks.CHUNK / line.length()).getBytes(StandardCharsets.US_ASCII);
            LineChunks chunks = new LineChunks(new ByteArrayInputStream(text));
            StringBuilder joined = new StringBuilder();
            int count = 0;
            for (Decoding.Text t = chunks.next(); t != null; t = chunks.next()) {
                assertTrue(t.text().endsWith(line.substring(line.indexOf('3'))), "cut after a whole line: " + line);
                count++;
                joined.append(t.text());
            }
            assertEquals(new String(text, StandardCharsets.US_ASCII), joined.toString(), "every byte once, in order");
            assertTrue(count >= 3, count + " chunks");
        }
    }

    @Test
    void inlineCommentsEndNamesAndLibraries() throws Exception {
        write("lib.mtl", "newmtl red # the red one\nKd 1 0 0 # rgb\n");
        ObjModel m = ObjLoader.load(write("m.obj", "mtllib lib.mtl # a note\no thing # object\ng part # group\n" + SQUARE
                                                   + "usemtl red # comment\nf 1 2 3 # face\n"), false);
        assertEquals("red", m.materials().get(0).name());
        assertArrayEquals(new double[] {1, 0, 0}, m.materials().get(0).kd(), 0);
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
    }

    @Test
    void backslashesSeparateFoldersInLibraryPaths() throws Exception {
        Files.createDirectories(dir.resolve("mtl"));
        write("mtl/lib.mtl", "newmtl red\nKd 1 0 0\n");
        ObjModel m = ObjLoader.load(write("m.obj", "mtllib .\\mtl\\lib.mtl\n" + SQUARE + "usemtl red\nf 1 2 3\n"), false);
        assertArrayEquals(new double[] {1, 0, 0}, m.materials().get(0).kd(), 0);
        assertTrue(m.warnings().isEmpty(), m.warnings().toString());
    }

    @Test
    void unknownKeywordsWarnOncePerKeywordWithACount() throws Exception {
        ObjModel m = ObjLoader.load(write("m.obj", SQUARE + "frob 1\nf 1 2 3\nfrob 2\nwarp\nfrob 3\n"), false);
        assertEquals(List.of(dir.resolve("m.obj") + ":5: unknown keyword 'frob' ignored (3 lines)",
                             dir.resolve("m.obj") + ":8: unknown keyword 'warp' ignored (1 line)"), m.warnings());
        // past the first few distinct keywords the file is likely not OBJ at all: the rest are counted together
        StringBuilder many = new StringBuilder(SQUARE + "f 1 2 3\n");
        for (int k = 1; k <= FileWarnings.KEYWORDS_NAMED + 12; k++) {
            many.append("kw").append(k).append(" 1\n");
        }
        List<String> warnings = ObjLoader.load(write("many.obj", many.toString()), false).warnings();
        assertEquals(FileWarnings.KEYWORDS_NAMED + 1, warnings.size(), warnings.toString());
        assertEquals(dir.resolve("many.obj") + ":" + (6 + FileWarnings.KEYWORDS_NAMED) + ": more unknown keywords ignored (12 lines)",
                     warnings.get(FileWarnings.KEYWORDS_NAMED));
    }

    @Test
    void aForeignFileIsNeverEchoed() throws Exception {
        // mtllib ../../etc/passwd: lines of someone else's file must not reach the warnings
        StringBuilder passwd = new StringBuilder();
        for (int i = 0; i < 40; i++) {
            passwd.append("user").append(i).append(":x:").append(1000 + i).append(":100:Secret Name ").append(i)
                  .append(":/home/user").append(i).append(":/bin/sh\n");
        }
        passwd.append("\u0001\u0002binary\u0007 stuff\n");
        write("passwd", passwd.toString());
        Files.createDirectories(dir.resolve("a"));
        ObjModel m = ObjLoader.load(write("a/m.obj", "mtllib ../passwd\n" + SQUARE + "f 1 2 3\n"), false);
        String all = String.join("\n", m.warnings());
        assertTrue(m.warnings().size() <= 10, all);
        assertTrue(all.contains(dir.resolve("passwd") + ":1: "), all);
        for (String secret : new String[] {"Secret", "/home", "/bin/sh", "\u0001", "\u0007", "1005"}) {
            assertTrue(!all.contains(secret), "'" + secret + "' echoed: " + all);
        }
    }

    @Test
    void anEmptyGzipSaysSo() throws IOException {
        Path gz = write("m.obj.gz", new byte[0]);
        ObjException e = assertThrows(ObjException.class, () -> ObjLoader.load(gz, false));
        assertEquals(gz + ": the file is empty (no gzip data)", e.getMessage());
    }
}

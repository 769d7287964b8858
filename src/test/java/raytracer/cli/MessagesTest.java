package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.RenderCommandTest.Result;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * Every bad input is one line naming its file and line, bounded in
 * length, with control and bidirectional characters of echoed names escaped; the same mistake has
 * the same exit status in both commands; what cannot be written is found before rendering.
 */
class MessagesTest {
    @TempDir
    Path dir;

    private static final String OBJECT = "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5}\n";

    private Path scene(String text) throws IOException {
        return Files.writeString(dir.resolve("s.yaml"), text, StandardCharsets.UTF_8);
    }

    private Result render(Path scene, String... more) {
        return RenderCommandTest.run(Stream.concat(Stream.of(scene.toString(), "-o", dir.resolve("o.png").toString(), "-q"),
                                                   Stream.of(more)).toArray(String[]::new));
    }

    /** One line, exit code {@code code}, starting with the file, its line and column ({@code where} their start). */
    private void assertOneLineAt(Result r, int code, String where, String fragment) {
        assertEquals(code, r.code(), r.err());
        assertEquals(1, r.lines().length, r.err());
        assertTrue(r.err().startsWith("render: error: " + dir.resolve("s.yaml") + ":" + where), r.err());
        assertTrue(r.err().matches("render: error: [^:]*s\\.yaml:\\d+:\\d+: .*\\R?"), r.err());
        assertTrue(r.err().contains(fragment), r.err());
    }

    @Test
    void anOverflowingTransformSaysSoWithItsLine() throws IOException {
        Result r = render(scene("objects:\n  - {type: sphere, center: [0, 0, 0],\n     transform: [{scale: 1e200}]}\n"));
        assertOneLineAt(r, 1, "3:17", "the transform overflows");
    }

    @Test
    void anImpossibleImageSizeNamesItsLine() throws IOException {
        Result r = render(scene("image: {width: 100000, height: 100000}\nobjects:\n" + OBJECT));
        assertOneLineAt(r, 1, "1:16", "100000 x 100000 pixels");
    }

    @Test
    void yamlLimitsNameTheirLine() throws IOException {
        Result r = render(scene("image: {width: 4, height: 4}\nobjects: " + "[".repeat(60) + "]".repeat(60) + "\n"));
        assertOneLineAt(r, 1, "2:", "nested deeper than");
        StringBuilder laughs = new StringBuilder("image: {width: 4, height: 4}\na: &a [x, x]\n");
        for (int i = 1; i < 60; i++) {
            laughs.append("a").append(i).append(": &a").append(i).append(" [*a").append(i == 1 ? "" : i - 1).append(", *a")
                  .append(i == 1 ? "" : i - 1).append("]\n");
        }
        r = render(scene(laughs + "objects:\n" + OBJECT));
        assertOneLineAt(r, 1, "", "aliases");
    }

    @Test
    void aListOfNamesInAMessageIsBounded() throws IOException {
        StringBuilder text = new StringBuilder("materials:\n");
        for (int i = 0; i < 20_000; i++) {
            text.append("  m").append(i).append(": {type: matte}\n");
        }
        Result r = render(scene(text + "objects:\n  - {type: sphere, center: [0, 0, 0], material: nope}\n"));
        assertEquals(1, r.code(), r.err());
        assertEquals(1, r.lines().length);
        assertTrue(r.err().length() < 1000, "a bounded line, got " + r.err().length() + " characters");
        assertTrue(r.err().contains("material 'nope' is not defined; defined: m0, m1,") && r.err().contains("and 19,990 more"),
                   r.err());
    }

    @Test
    void controlAndBidiCharactersInNamesAreEscaped() throws IOException {
        Result r = render(scene("objects:\n  - {type: mesh, file: \"a\\e[31mred\\a\\0\\u202Eevil.obj\"}\n"));
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("a\\x1b[31mred\\x07\\x00\\u202eevil.obj"), r.err());
        assertFalse(r.err().chars().anyMatch(c -> c < 0x20 && c != '\n' || c == 0x202e), "raw control characters: " + r.err());
    }

    @Test
    void convergeAndRenderGiveOneStatusForABadThreadCount() throws IOException {
        Path s = scene("image: {width: 4, height: 4, samples: 1}\nobjects:\n" + OBJECT);
        assertEquals(2, render(s, "-t", "40000").code());
        Result r = RenderCommandTest.run("converge", s.toString(), "-t", "40000", "--plot", dir.resolve("p.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--threads must be 1 to 32767, got 40000"), r.err());
    }

    @Test
    void aFileNameTooLongForTheTemporaryFileFailsBeforeRendering() throws IOException {
        Path s = scene("image: {width: 4, height: 4, samples: 1}\nobjects:\n" + OBJECT);
        Result r = RenderCommandTest.run(s.toString(), "-o", dir.resolve("x".repeat(300) + ".png").toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("the file name is 304 bytes long"), r.err());
    }

    @Test
    void aPfmWithCrlfLineEndsReadsAsWritten() throws IOException {
        Film film = new Film(2, 1);
        film.set(0, 0, 0.25, 0.5, 1);
        film.set(1, 0, 2, 4, 8);
        ByteBuffer data = ByteBuffer.allocate(24).order(ByteOrder.LITTLE_ENDIAN);
        for (int x = 0; x < 2; x++) {
            for (int c = 0; c < 3; c++) {
                data.putFloat(film.get(x, 0, c));
            }
        }
        byte[] header = "PF\r\n2 1\r\n-1.0\r\n".getBytes(StandardCharsets.US_ASCII);
        byte[] bytes = new byte[header.length + 24];
        System.arraycopy(header, 0, bytes, 0, header.length);
        System.arraycopy(data.array(), 0, bytes, header.length, 24);
        Path pfm = Files.write(dir.resolve("crlf.pfm"), bytes);
        Film read = ImageWriters.readPfm(pfm);
        assertEquals(8, read.get(1, 0, 2));
        assertEquals(0.25, read.get(0, 0, 0));
    }

    @Test
    void anEnvironmentHidesTheBackgroundWithAWarning() throws IOException {
        Path s = scene("image: {width: 4, height: 4, samples: 1}\nbackground: [1, 0, 0]\n"
                       + "environment: {file: " + Path.of("assets/env/venice_sunset_1k.hdr").toAbsolutePath() + "}\nobjects:\n" + OBJECT);
        Result r = RenderCommandTest.run(s.toString(), "-o", dir.resolve("o.png").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("render: warning: " + s + ":2:13: 'background' is not used"), r.err());
    }

    @Test
    void anEmptyCacheFolderIsAUsageError() throws IOException {
        Path s = scene("image: {width: 4, height: 4, samples: 1}\nobjects:\n" + OBJECT);
        Result r = render(s, "--cache-dir", "");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--cache-dir must name a folder"), r.err());
        r = RenderCommandTest.run("converge", s.toString(), "--cache", "", "--plot", dir.resolve("p.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--cache must name a folder"), r.err());
    }

    @Test
    void theCacheSaysWhyInWordsNotWithAPath() throws IOException {
        // large enough to be cached (MeshCache.MIN_OBJ_BYTES)
        Files.writeString(dir.resolve("t.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n".repeat(30_000));
        Path s = scene("image: {width: 4, height: 4, samples: 1}\nobjects:\n  - {type: mesh, file: t.obj}\n");
        Path cache = Files.writeString(dir.resolve("cache"), "a file where the folder should be");
        Result r = RenderCommandTest.run(s.toString(), "-o", dir.resolve("o.png").toString(), "--cache-dir", cache.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("(" + cache + " is a regular file, not a folder)"), r.err());
        Files.delete(cache);
        Files.createSymbolicLink(cache, dir.resolve("loop"));
        Files.createSymbolicLink(dir.resolve("loop"), cache);
        r = RenderCommandTest.run(s.toString(), "-o", dir.resolve("o.png").toString(), "--cache-dir", cache.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("(" + cache + " is a loop of symbolic links, not a folder)"), r.err());
        assertFalse(r.err().contains("(null)") || r.err().contains("(" + cache + ")"), r.err());
    }
}

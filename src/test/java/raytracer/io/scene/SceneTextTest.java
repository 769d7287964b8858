package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.error.MarkedYAMLException;
import org.yaml.snakeyaml.reader.StreamReader;
import org.yaml.snakeyaml.scanner.ScannerImpl;
import org.yaml.snakeyaml.tokens.Token;
import raytracer.core.World;

/** The scene reader: linear in the length of any token, with SnakeYAML's own line and column counting. */
class SceneTextTest {
    private static final String SPHERE = "image: {width: 8, height: 8, samples: 1}\nobjects:\n  - {type: sphere, center: [0, 0, 0]}\n";

    @Test
    void oneLongCommentLineLoadsInLinearTime() {
        // SnakeYAML's reader took 4.4 s for a 4 MiB comment and over a minute for 16 MiB (quadratic)
        String comment = "# " + "x".repeat(16 << 20) + "\n";
        World world = assertTimeoutPreemptively(Duration.ofSeconds(10), () -> SceneLoader.load("long.yaml", comment + SPHERE).world());
        assertEquals(1, world.objects().size());
    }

    @Test
    void longWordsAndRunsOfSpacesToo() {
        String spaces = SPHERE + " ".repeat(8 << 20) + "\n";
        assertTimeoutPreemptively(Duration.ofSeconds(10), () -> SceneLoader.load("spaces.yaml", spaces));
        String word = "tracer: " + "w".repeat(8 << 20) + "\n" + SPHERE;
        SceneException e = assertTimeoutPreemptively(Duration.ofSeconds(10),
            () -> assertThrows(SceneException.class, () -> SceneLoader.load("word.yaml", word)));
        assertTrue(e.getMessage().startsWith("word.yaml:1:9: unknown tracer"), e.getMessage().substring(0, 60));
    }

    @Test
    void aGeneratedSceneOverSnakeYamlsDefaultLimitLoads() throws SceneException {
        // a 4.9 MB scene of 66,576 spheres was refused as "syntax error: The incoming YAML document
        // exceeds the limit: 3145728 code points"; this one is 3.3 MB, with numbers as a program prints them
        StringBuilder text = new StringBuilder(SPHERE);
        for (int i = 0; i < 24_000; i++) {
            text.append("  - {type: sphere, center: [").append(i % 160 + 0.1234567890123456).append(", ")
                .append(i / 160 - 0.9876543210987654).append(", -20.000000000000004], radius: 0.15000000000000002, ")
                .append("casts-shadows: true}\n");
        }
        assertTrue(text.length() > 3 << 20, "size " + text.length());
        assertEquals(24_001, SceneLoader.load("many.yaml", text.toString()).world().objects().size());
    }

    @Test
    void aSceneOverTheLimitIsRefusedWithTheLimit() {
        String text = SPHERE + "#" + "x".repeat(SceneLoader.MAX_CHARACTERS - SPHERE.length());
        assertEquals(SceneLoader.MAX_CHARACTERS + 1, text.length());
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load("huge.yaml", text));
        assertEquals("huge.yaml: the scene file has more than the 67108864 characters a scene may hold "
                     + "(put large meshes in OBJ files)", e.getMessage());
    }

    /**
     * A scene file that never ends (/dev/zero, only read here) or is longer than the limit through a
     * pipe is read only up to the limit, then refused with it: before, /dev/zero was read for 17 s
     * until the heap ran out.
     */
    @Test
    void aSceneThatNeverEndsStopsAtTheLimit(@TempDir Path dir) throws Exception {
        SceneException zero = assertTimeoutPreemptively(Duration.ofSeconds(30),
            () -> assertThrows(SceneException.class, () -> SceneLoader.load(Path.of("/dev/zero"))));
        assertEquals("/dev/zero: the scene file has more than the 67108864 characters a scene may hold "
                     + "(put large meshes in OBJ files)", zero.getMessage());
        Path fifo = dir.resolve("scene.yaml");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        Thread writer = new Thread(() -> {
            try (OutputStream out = Files.newOutputStream(fifo)) {
                byte[] comment = ("#" + "x".repeat(1 << 16) + "\n").getBytes(StandardCharsets.US_ASCII);
                for (int i = 0; i < 2000; i++) {
                    out.write(comment);
                }
            } catch (IOException e) {
                // the reader stopped at the limit and closed its end: the pipe is broken, as expected
            }
        }, "scene writer");
        writer.setDaemon(true);
        writer.start();
        SceneException piped = assertTimeoutPreemptively(Duration.ofSeconds(30),
            () -> assertThrows(SceneException.class, () -> SceneLoader.load(fifo)));
        assertTrue(piped.getMessage().contains("more than the 67108864 characters"), piped.getMessage());
        // a scene through a pipe within the limit is read as from a file
        assertEquals(0, new ProcessBuilder("rm", fifo.toString()).start().waitFor());
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        Thread small = new Thread(() -> {
            try {
                Files.writeString(fifo, SPHERE);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }, "scene writer");
        small.setDaemon(true);
        small.start();
        assertEquals(1, assertTimeoutPreemptively(Duration.ofSeconds(30), () -> SceneLoader.load(fifo)).world().objects().size());
    }

    @Test
    void aCharacterYamlDoesNotAllowIsNamedWithItsPlace() {
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load("bell.yaml", SPHERE + "# ring \u0007\n"));
        assertEquals("bell.yaml:4:8: character U+0007 is not allowed in a YAML file", e.getMessage());
    }

    /** Every token's kind, start and end (line, column and index), and where scanning failed if it did. */
    private static List<String> tokens(StreamReader reader) {
        ScannerImpl scanner = new ScannerImpl(reader, new LoaderOptions());
        List<String> out = new ArrayList<>();
        try {
            while (scanner.checkToken()) {
                Token t = scanner.getToken();
                out.add(t.getTokenId() + " " + where(t.getStartMark()) + " - " + where(t.getEndMark()));
            }
        } catch (MarkedYAMLException e) {
            out.add(e.getProblem() + " " + where(e.getProblemMark()));
        }
        return out;
    }

    private static String where(Mark mark) {
        return mark.getLine() + ":" + mark.getColumn() + "@" + mark.getIndex();
    }

    @Test
    void linesAndColumnsAreCountedAsSnakeYamlCountsThem() {
        String[] texts = {
            SPHERE,
            "\uFEFFa: 1\nb: [1, 2]\n",                         // byte-order mark: no column
            "a: 1\r\nb: 2\rc: 3\n\u0085d: 4\u2028e: 5\u2029f: 6", // CRLF is one break; CR, NEL, LS, PS alone too
            "a: \"\uD83D\uDE00 x\"\nb: |\n  one\n  two\n# comment\nc: 'q'\r",  // a supplementary character is one column
            "list:\n  - {x: [1, 2, 3]}   # after\n  - >\n    folded\n    text\n...\n",
            "\ta: 1\n",                                       // a tab cannot start a token: both fail at 0:0
            "a: [1,\n  2\n",                                   // and this at the end
        };
        for (String text : texts) {
            assertTrue(tokens(new SceneText("t", text)).size() >= 2, text);
            assertEquals(tokens(new StreamReader(new StringReader(text))), tokens(new SceneText("t", text)), text);
        }
    }

    @Test
    void unprintableCharactersAreFound() {
        assertEquals(-1, SceneText.firstUnprintable("a: \uD83D\uDE00\t\r\n\u0085"));
        assertEquals(3, SceneText.firstUnprintable("a: \u0007"));
        assertEquals(2, SceneText.firstUnprintable("a\n\u0000"));
        assertEquals(1, SceneText.firstUnprintable("a\uFFFE"));
        assertFalse(SceneText.firstUnprintable("\uD800") == -1, "a lone surrogate");
    }
}

package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every scene of scenes/ renders to the same bytes as recorded in {@link #DIGESTS}, with the book's
 * box filter and with the Gaussian: a change of the code's form (a class split, a loop moved) must
 * leave every image as it was, to the bit. A change that alters images on purpose records them
 * again ({@code gradle junit -Ptests=raytracer.cli.SceneImagesTest -PupdateDigests}) and says in
 * its commit which scenes changed and why; any other difference fails here, naming the scene.
 * The images are small (96x54, 4 samples a pixel) but reach every shading path the scenes use.
 */
class SceneImagesTest {
    static final Path DIGESTS = Path.of("src/test/resources/scene-digests.tsv");
    private static final String[] RENDER = {"-W", "96", "-H", "54", "--spp", "4", "--seed", "11", "-t", "2", "-q"};
    private static final String[] FILTERS = {"box", "gaussian"};

    @TempDir
    static Path dir;

    /** scene and filter, tab-separated, to the SHA-256 of the .pfm (linear float) render. */
    private static Map<String, String> recorded() throws IOException {
        Map<String, String> digests = new LinkedHashMap<>();
        if (Files.exists(DIGESTS)) {
            for (String line : Files.readAllLines(DIGESTS, StandardCharsets.UTF_8)) {
                if (!line.isBlank() && !line.startsWith("#")) {
                    int tab = line.lastIndexOf('\t');
                    digests.put(line.substring(0, tab), line.substring(tab + 1));
                }
            }
        }
        return digests;
    }

    @TestFactory
    Stream<DynamicTest> everySceneRendersAsRecorded() throws IOException {
        boolean update = Boolean.getBoolean("raytracer.updateDigests");
        Map<String, String> recorded = recorded();
        Map<String, String> rendered = new LinkedHashMap<>();
        List<DynamicTest> tests = new ArrayList<>();
        List<Path> scenes = SceneFilesTest.sceneFiles().toList();
        for (Path scene : scenes) {
            for (String filter : FILTERS) {
                String key = scene.getFileName() + "\t" + filter;
                tests.add(DynamicTest.dynamicTest(key.replace('\t', ' '), () -> {
                    String digest = render(scene, filter);
                    rendered.put(key, digest);
                    if (!update) {
                        assertTrue(recorded.containsKey(key), key + " has no recorded digest in " + DIGESTS
                                                              + " (record it with -PupdateDigests)");
                        assertEquals(recorded.get(key), digest, key + ": the image changed");
                    }
                }));
            }
        }
        tests.add(DynamicTest.dynamicTest("every recorded scene still exists", () -> {
            if (update) {
                StringBuilder text = new StringBuilder("# scene, filter, SHA-256 of its .pfm: SceneImagesTest\n");
                rendered.forEach((k, v) -> text.append(k).append('\t').append(v).append('\n'));
                Files.writeString(DIGESTS, text, StandardCharsets.UTF_8);
            } else {
                List<String> gone = new ArrayList<>(recorded.keySet());
                gone.removeAll(rendered.keySet());
                assertEquals(List.of(), gone, "digests of scenes no longer in scenes/");
            }
        }));
        return tests.stream();
    }

    private static String render(Path scene, String filter) throws Exception {
        Path out = dir.resolve(scene.getFileName() + "-" + filter + ".pfm");
        List<String> args = new ArrayList<>(List.of(scene.toString(), "-o", out.toString(), "--filter", filter));
        args.addAll(List.of(RENDER));
        RenderCommandTest.Result r = RenderCommandTest.run(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.err());
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(out)));
    }
}

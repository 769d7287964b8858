package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * Every scene in scenes/ renders to the same bits with the scene analysis and without it
 * ({@code --no-skip}), through the command line as a user would check it. Each scene is one test;
 * a last one checks that the comparison means something: the analysed renders did less work (fewer
 * rays of some kind, or fewer box tests per ray) in several scenes, so a {@code --no-skip} that did
 * nothing, leaving both runs analysed, fails here.
 */
class NoSkipTest {
    /** Small and at one sample: the whole class is a few seconds, the dragon's parse and build included. */
    private static final String[] RENDER = {"-W", "96", "-H", "54", "--spp", "1", "--seed", "7", "-t", "2", "--no-cache", "--stats", "-q"};
    /** Scenes whose analysed render did measurably less work; today 10 (shadow rays left out, tile search). */
    private static final int SCENES_THAT_SAVE_AT_LEAST = 5;
    private static final Pattern RAYS = Pattern.compile("stats: rays (\\d+) \\(primary (\\d+), shadow (\\d+), secondary (\\d+)\\)");
    private static final Pattern BOX_TESTS = Pattern.compile("stats: ([0-9.]+) bounding-volume tests");

    @TempDir
    Path dir;

    /** What --stats said of the work: rays by kind (primary, shadow, secondary), then box tests per ray. */
    private record Work(double[] counts, String err) {
        static Work of(String err) {
            Matcher rays = RAYS.matcher(err);
            Matcher box = BOX_TESTS.matcher(err);
            assertTrue(rays.find() && box.find(), "no --stats figures in:\n" + err);
            return new Work(new double[] {Double.parseDouble(rays.group(2)), Double.parseDouble(rays.group(3)),
                                          Double.parseDouble(rays.group(4)), Double.parseDouble(box.group(1))}, err);
        }

        /**
         * More rays of some kind, or the same rays and more box tests per ray (a per-ray figure is
         * compared only over the same rays: shadow rays left out change what it averages over).
         */
        boolean moreThan(Work other) {
            boolean sameRays = true;
            for (int i = 0; i < 3; i++) {
                if (counts[i] > other.counts[i]) {
                    return true;
                }
                sameRays &= counts[i] == other.counts[i];
            }
            return sameRays && counts[3] > other.counts[3];
        }
    }

    @TestFactory
    Stream<DynamicTest> everySceneIsTheSameWithoutTheAnalysis() throws IOException {
        List<Path> scenes = SceneFilesTest.sceneFiles().toList();
        List<String> saving = new ArrayList<>();
        List<DynamicTest> tests = new ArrayList<>();
        for (Path scene : scenes) {
            tests.add(DynamicTest.dynamicTest(scene.toString(), () -> {
                Work analysed = render(scene, "analysed.pfm");
                Work given = render(scene, "given.pfm", "--no-skip");
                assertSameBits(scene, ImageWriters.readPfm(dir.resolve("analysed.pfm")), ImageWriters.readPfm(dir.resolve("given.pfm")));
                assertTrue(given.err().contains("stats: skip: nothing (--no-skip: the scene analysis was off"), given.err());
                // the analysis leaves work out, it never adds any
                assertTrue(!analysed.moreThan(given), "the analysed render did more work than the unanalysed one:\n"
                                                      + analysed.err() + "\n--no-skip:\n" + given.err());
                if (given.moreThan(analysed)) {
                    saving.add(scene.getFileName().toString());
                }
            }));
        }
        tests.add(DynamicTest.dynamicTest("the analysed renders left something out", () ->
            assertTrue(saving.size() >= SCENES_THAT_SAVE_AT_LEAST,
                       "--no-skip changed the work of only " + saving + " of " + scenes.size() + " scenes")));
        return tests.stream();
    }

    private Work render(Path scene, String image, String... more) {
        List<String> args = new ArrayList<>(List.of(scene.toString(), "-o", dir.resolve(image).toString()));
        args.addAll(List.of(RENDER));
        args.addAll(List.of(more));
        RenderCommandTest.Result r = RenderCommandTest.run(args.toArray(String[]::new));
        assertEquals(0, r.code(), r.err());
        return Work.of(r.err());
    }

    /** The same float bits in every channel of every pixel; on failure, the first pixel that differs and how many do. */
    private static void assertSameBits(Path scene, Film analysed, Film given) {
        assertEquals(given.width(), analysed.width());
        assertEquals(given.height(), analysed.height());
        int differ = 0;
        String first = null;
        for (int y = 0; y < given.height(); y++) {
            for (int x = 0; x < given.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    if (Float.floatToRawIntBits(analysed.get(x, y, c)) != Float.floatToRawIntBits(given.get(x, y, c))) {
                        differ++;
                        if (first == null) {
                            first = String.format("pixel (%d, %d) channel %d: analysed %s, --no-skip %s", x, y, c,
                                                  analysed.get(x, y, c), given.get(x, y, c));
                        }
                    }
                }
            }
        }
        if (differ > 0) {
            fail(scene + ": the analysis changed " + differ + " channel values; first " + first);
        }
    }
}

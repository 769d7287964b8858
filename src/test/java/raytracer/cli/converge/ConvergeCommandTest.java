package raytracer.cli.converge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.RenderCommand;
import raytracer.cli.RenderCommandTest;
import raytracer.cli.RenderCommandTest.Result;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * {@code render converge} end to end on tiny images: the table's rows (read from --csv), the plot,
 * the closed-form and the cached self-rendered references, and one clear line for each mistake.
 */
class ConvergeCommandTest {
    @TempDir
    Path dir;

    private static final String SPHERES = """
        image: {width: 16, height: 12, samples: 4}
        ambient: {radiance: 0}
        camera: {eye: [0, 2, 5], look-at: [0, 0.5, 0], fov: 40}
        lights:
          - {type: rectangle, corner: [-1, 3, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], radiance: 8, samples: 1, visible: false}
        objects:
          - {type: plane, normal: [0, 1, 0]}
          - {type: sphere, center: [0, 0.7, 0], radius: 0.7}
        """;

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    private static Result converge(String... args) {
        return RenderCommandTest.run(Stream.concat(Stream.of("converge"), Stream.of(args)).toArray(String[]::new));
    }

    /** The names of the reference cache's entries in {@code folder}, sorted (not its lock file). */
    private static List<String> entries(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".ref")).sorted().toList();
        }
    }

    /** The CSV's data lines, split into fields (the quoted configuration name first). */
    private static List<String[]> rows(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        assertTrue(lines.get(0).startsWith("configuration,spp,light_samples,seconds,rmse,relative_rmse"), lines.get(0));
        return lines.stream().skip(1).map(l -> l.split(",(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)")).toList();
    }

    @Test
    void measuresEachConfigurationAgainstTheExactImageAndPlotsThem() throws IOException {
        Path csv = dir.resolve("t.csv");
        Path plot = dir.resolve("p.png");
        Result r = converge(Path.of("scenes", "closed-form-rectangle.yaml").toString(), "-W", "16", "-H", "16", "--spp", "1,16",
                            "--config", "sampler=random/jittered,light-samples=1", "--csv", csv.toString(), "--plot", plot.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("reference: the exact image (closed form)"), r.err());
        assertTrue(r.err().contains("[4/4] jittered, 1 light sample: 16 spp"), r.err());
        List<String[]> rows = rows(csv);
        assertEquals(4, rows.size());
        assertEquals("\"random, 1 light sample\"", rows.get(0)[0]);
        assertEquals("16", rows.get(3)[1]);
        for (int i = 0; i < 4; i += 2) {
            double at1 = Double.parseDouble(rows.get(i)[5]);
            double at16 = Double.parseDouble(rows.get(i + 1)[5]);
            // 16 times the samples: about a quarter of the error (stratified pixels may do better)
            assertTrue(at16 < at1 / 2.5, "relative RMSE at 1 spp " + at1 + ", at 16 spp " + at16);
        }
        BufferedImage image = ImageIO.read(plot.toFile());
        assertEquals(ConvergeRun.PLOT_WIDTH, image.getWidth());
        assertEquals(ConvergeRun.PLOT_HEIGHT, image.getHeight());
    }

    @Test
    void errorsAreMeasuredInTheUnitsOfThePfmOutput() throws IOException {
        // exposure scales the image and the exact image alike: the relative error does not change
        String text = Files.readString(Path.of("scenes", "closed-form-disk.yaml"));
        String brightText = text.replace("samples: 16}", "samples: 16, exposure: 3}");
        assertNotEquals(text, brightText, "the scene's image line changed: the exposure was not added");
        Path bright = write("bright.yaml", brightText);
        Path plain = write("plain.yaml", text);
        double[] relative = new double[2];
        double[] rmse = new double[2];
        Path[] scenes = {plain, bright};
        for (int i = 0; i < 2; i++) {
            Path csv = dir.resolve(i + ".csv");
            Result r = converge(scenes[i].toString(), "-W", "12", "-H", "12", "--spp", "4", "-q", "--csv", csv.toString(),
                                "--plot", dir.resolve(i + ".png").toString());
            assertEquals(0, r.code(), r.err());
            relative[i] = Double.parseDouble(rows(csv).get(0)[5]);
            rmse[i] = Double.parseDouble(rows(csv).get(0)[4]);
        }
        assertTrue(relative[0] > 0, "4 spp of a soft-lit disk have some error: " + relative[0]);
        assertEquals(relative[0], relative[1], 1e-6 * relative[0]);
        assertEquals(3 * rmse[0], rmse[1], 1e-6 * rmse[1]);
    }

    @Test
    void aSelfRenderedReferenceIsCachedAndReused() throws IOException {
        Path scene = write("spheres.yaml", SPHERES);
        Path cache = dir.resolve("cache");
        String[] args = {scene.toString(), "--spp", "1,4", "--time", "0.01", "--reference-spp", "64", "--cache", cache.toString(),
                         "--csv", dir.resolve("a.csv").toString(), "--plot", dir.resolve("a.png").toString()};
        Result first = converge(args);
        assertEquals(0, first.code(), first.err());
        // 64 spp in two halves of 32, which the multi-jittered pattern rounds to 36
        assertTrue(first.err().contains("rendering the reference: 2 x 36 spp, seeds -2 and " + (-2 ^ ConvergeReference.OTHER_HALF)),
                   first.err());
        List<String> names = entries(cache);
        assertEquals(1, names.size(), names.toString());
        assertTrue(names.get(0).matches("spheres-[0-9a-f]{16}\\.ref"), names.toString());
        List<String[]> firstCsv = rows(dir.resolve("a.csv"));
        assertEquals(3, firstCsv.size(), "1 and 4 spp and one time budget");
        args[args.length - 3] = dir.resolve("b.csv").toString();
        Result second = converge(args);
        assertEquals(0, second.code(), second.err());
        assertTrue(second.err().contains("reused"), second.err());
        assertFalse(second.err().contains("rendering the reference"), second.err());
        // the same renders against the same reference: the same errors (times differ)
        List<String[]> secondCsv = rows(dir.resolve("b.csv"));
        for (int i = 0; i < 2; i++) {
            assertEquals(firstCsv.get(i)[4], secondCsv.get(i)[4]);
        }
        // another seed for the measured renders keeps the reference, another reference spp does not
        Result other = converge(scene.toString(), "--spp", "1", "--reference-spp", "16", "--cache", cache.toString(), "-q",
                                "--plot", dir.resolve("c.png").toString());
        assertEquals(0, other.code(), other.err());
        assertEquals(2, entries(cache).size());
    }

    /**
     * A cached reference is used only when it matches the checksum its entry holds. Before, a NaN pixel in it gave an RMSE of NaN and exit 0, and a changed
     * value was reused silently; and --cache naming a file failed only after the reference was rendered.
     */
    @Test
    void aChangedCachedReferenceIsRenderedAgain() throws IOException {
        Path scene = write("spheres.yaml", SPHERES);
        Path cache = dir.resolve("cache");
        Path csv = dir.resolve("a.csv");
        String[] args = {scene.toString(), "--spp", "1", "--reference-spp", "16", "--cache", cache.toString(), "--csv",
                         csv.toString(), "--plot", dir.resolve("a.png").toString()};
        assertEquals(0, converge(args).code());
        String rmse = rows(csv).get(0)[4];
        Path pfm = cache.resolve(entries(cache).get(0));
        byte[] good = Files.readAllBytes(pfm);
        for (float bad : new float[] {Float.NaN, 0.123f}) {
            byte[] changed = good.clone();
            // the last pixel's blue channel, little-endian: the entry ends with the image as a .pfm holds it
            int bits = Float.floatToRawIntBits(bad);
            for (int k = 0; k < 4; k++) {
                changed[changed.length - 4 + k] = (byte) (bits >>> 8 * k);
            }
            Files.write(pfm, changed);
            Result r = converge(args);
            assertEquals(0, r.code(), r.err());
            assertTrue(r.err().contains("does not match its checksum; rendering it again"), r.err());
            assertTrue(r.err().contains("rendering the reference"), r.err());
            assertEquals(rmse, rows(csv).get(0)[4], "the same reference as first rendered");
        }
    }

    /**
     * The cached reference is keyed by the content of every file the scene reads: a changed
     * texture or mesh renders it again. Before, only the scene file and the settings were in the
     * key, and a changed texture measured an RMSE 28 times too high against the old reference.
     */
    @Test
    void aChangedTextureOrMeshRendersTheReferenceAgain() throws IOException {
        BufferedImage red = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        red.setRGB(0, 0, 0xff2020);
        ImageIO.write(red, "png", dir.resolve("t.png").toFile());
        write("m.obj", "v -1 0 -1\nv 1 0 -1\nv 0 1.5 0\nf 1 2 3\n");
        Path scene = write("textured.yaml", SPHERES.replace("- {type: plane, normal: [0, 1, 0]}",
            "- {type: plane, normal: [0, 1, 0], material: floor}\n  - {type: mesh, file: m.obj}")
            + "materials:\n  floor: {type: matte, texture: {type: image, file: t.png}}\n");
        String[] args = {scene.toString(), "--spp", "1", "--reference-spp", "16", "--cache", dir.resolve("cache").toString(),
                         "--plot", dir.resolve("a.png").toString()};
        Result first = converge(args);
        assertEquals(0, first.code(), first.err());
        assertTrue(first.err().contains("rendering the reference"), first.err());
        Result same = converge(args);
        assertTrue(same.err().contains("reused"), same.err());
        red.setRGB(0, 0, 0x20ff20);
        ImageIO.write(red, "png", dir.resolve("t.png").toFile());
        Result texture = converge(args);
        assertEquals(0, texture.code(), texture.err());
        assertTrue(texture.err().contains("rendering the reference"), "a changed texture: " + texture.err());
        write("m.obj", "v -1 0 -1\nv 1 0 -1\nv 0 1.2 0\nf 1 2 3\n");
        Result mesh = converge(args);
        assertTrue(mesh.err().contains("rendering the reference"), "a changed mesh: " + mesh.err());
        assertTrue(converge(args).err().contains("reused"));
    }

    @Test
    void aCacheThatIsAFileFailsBeforeRendering() throws IOException {
        Path scene = write("spheres.yaml", SPHERES);
        Path file = write("cache", "not a folder");
        Result r = converge(scene.toString(), "--spp", "1", "--reference-spp", "16", "--cache", file.toString(), "--plot",
                            dir.resolve("a.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--cache " + file + " is a regular file, not a folder"), r.err());
        assertFalse(r.err().contains("rendering the reference"), r.err());
    }

    @Test
    void aGivenReferenceFileIsUsedAndABadOneIsOneLine() throws IOException {
        Path scene = write("spheres.yaml", SPHERES);
        Path ref = dir.resolve("ref.pfm");
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--spp", "64", "--seed", "9", "-o", ref.toString(), "-q").code());
        Path csv = dir.resolve("r.csv");
        Result r = converge(scene.toString(), "--spp", "4", "--reference", ref.toString(), "--csv", csv.toString(),
                            "--plot", dir.resolve("r.png").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(Double.parseDouble(rows(csv).get(0)[5]) > 0);

        Path small = dir.resolve("small.pfm");
        ImageWriters.write(new Film(8, 8), 1, small);
        assertOneLine(converge(scene.toString(), "--reference", small.toString(), "--plot", dir.resolve("x.png").toString()),
                      1, "reference " + small + " is 8x8 but the image is 16x12");
        Path png = write("fake.pfm", "not an image");
        assertOneLine(converge(scene.toString(), "--reference", png.toString(), "--plot", dir.resolve("x.png").toString()),
                      1, png + ": not a PFM image");
        assertOneLine(converge(scene.toString(), "--reference", dir.resolve("none.pfm").toString(), "--plot",
                               dir.resolve("x.png").toString()), 1, "no such file");
        assertOneLine(converge(scene.toString(), "--reference", "closed-form", "--plot", dir.resolve("x.png").toString()),
                      1, "no closed form: the camera must be orthographic");
    }

    /**
     * An animated scene converges frame 0, as render renders it without --frames, and says so;
     * --frame N converges another (its reference is that frame's image), and a frame the scene
     * does not have is one line.
     */
    @Test
    void anAnimatedSceneConvergesFrameZeroOrTheFrameAsked() throws IOException {
        // the sphere off the axis of the orbit: each frame sees it elsewhere
        Path scene = write("turn.yaml", SPHERES.replace("center: [0, 0.7, 0]", "center: [1, 0.7, 0]") + """
            animation:
              frames: 4
              camera: {orbit: {center: [0, 0.5, 0], degrees: 120}}
            """);
        Result zero = converge(scene.toString(), "--spp", "1", "--reference-spp", "4", "--no-cache", "--plot",
                               dir.resolve("z.png").toString());
        assertEquals(0, zero.code(), zero.err());
        assertTrue(zero.err().contains("converge: the scene is animated; converging frame 0 of its 4 (--frame N picks another)"),
                   zero.err());
        Path ref = dir.resolve("ref-%d.pfm");
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--frames", "3", "--spp", "64", "-o", ref.toString(), "-q").code());
        double[] error = new double[2];
        for (int i = 0; i < 2; i++) {
            Path csv = dir.resolve(i + ".csv");
            Result r = converge(scene.toString(), "--frame", i == 0 ? "3" : "0", "--spp", "16", "--reference",
                                dir.resolve("ref-3.pfm").toString(), "-q", "--csv", csv.toString(), "--plot",
                                dir.resolve(i + ".png").toString());
            assertEquals(0, r.code(), r.err());
            error[i] = Double.parseDouble(rows(csv).get(0)[5]);
        }
        assertTrue(error[0] < error[1] / 2, "frame 3 against its own image " + error[0] + ", frame 0 against it " + error[1]);
        assertOneLine(converge(scene.toString(), "--frame", "4"), 2, "--frame 4: the scene's animation has 4 frames, 0 to 3");
        assertOneLine(converge(write("still.yaml", SPHERES).toString(), "--frame", "1"), 2,
                      "--frame 1: the scene has no animation section (a still is frame 0)");
        assertOneLine(converge(scene.toString(), "--reference", "closed-form", "-q", "--plot", dir.resolve("c.png").toString()), 1,
                      "no closed form: the scene is animated");
    }

    @Test
    void theSrgbMetricMeasuresTheDisplayedValues() throws IOException {
        // the same renders measured both ways: the sRGB curve stretches the dark values, so the
        // errors differ, and the reference's linear noise is not claimed for the displayed values
        Path linearCsv = dir.resolve("linear.csv");
        Path srgbCsv = dir.resolve("srgb.csv");
        String scene = Path.of("scenes", "closed-form-rectangle.yaml").toString();
        Result linear = converge(scene, "-W", "16", "-H", "16", "--spp", "4", "--csv", linearCsv.toString(),
                                 "--plot", dir.resolve("l.png").toString());
        Result srgb = converge(scene, "-W", "16", "-H", "16", "--spp", "4", "--metric", "srgb", "--csv", srgbCsv.toString(),
                               "--plot", dir.resolve("s.png").toString());
        assertEquals(0, linear.code(), linear.err());
        assertEquals(0, srgb.code(), srgb.err());
        assertTrue(srgb.err().contains("converge: metric: the displayed values, clamped to [0, 1] and sRGB-encoded"), srgb.err());
        assertFalse(linear.err().contains("metric:"), linear.err());
        double l = Double.parseDouble(rows(linearCsv).get(0)[5]);
        double s = Double.parseDouble(rows(srgbCsv).get(0)[5]);
        assertTrue(l > 0 && s > 0 && Math.abs(l - s) > 0.01 * l, "relative RMSE linear " + l + ", sRGB " + s);
    }

    /**
     * converge takes render's options, declared and checked once for both: the mesh cache among
     * them, which before it did not have (each configuration parsed every mesh again, every run).
     */
    @Test
    void theOptionsSharedWithRenderIncludeTheMeshCache() throws IOException {
        // a quad, and enough copies of its face to be worth caching
        write("quad.obj", "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n" + "f 1 2 3 4\n".repeat(25_000));
        Path scene = write("mesh.yaml", SPHERES.replace("- {type: plane, normal: [0, 1, 0]}", "- {type: mesh, file: quad.obj}"));
        Path meshes = dir.resolve("meshes");
        Result r = converge(scene.toString(), "--spp", "1", "--config", "sampler=random/jittered", "--reference-spp", "4",
                            "--cache", dir.resolve("references").toString(), "--cache-dir", meshes.toString(), "--accel", "sah",
                            "--max-depth", "2", "-q", "--plot", dir.resolve("m.png").toString());
        assertEquals(0, r.code(), r.err());
        try (Stream<Path> files = Files.list(meshes)) {
            assertEquals(1, files.filter(p -> p.toString().endsWith(".mesh")).count(), "one entry for the base and both curves");
        }
        assertOneLine(converge(scene.toString(), "--no-cache", "--cache-dir", meshes.toString()), 2,
                      "--no-cache and --cache-dir exclude each other");
        assertOneLine(converge(scene.toString(), "--cache-max", "lots"), 2, "--cache-max: a size such as 512M or 2G is expected");
        assertOneLine(converge(scene.toString(), "-W", "0"), 2, "--width must be at least 1, got 0");
        assertOneLine(converge(scene.toString(), "--sampler", "poisson-disk"), 2, "unknown sampler 'poisson-disk'");
        StringWriter help = new StringWriter();
        assertEquals(0, RenderCommand.run(new PrintWriter(help, true), new PrintWriter(new StringWriter(), true), "converge", "--help"));
        assertTrue(help.toString().contains("--cache-dir=DIR") && help.toString().contains("Neither read nor write cached references or meshes")
                   && help.toString().contains("Seed of the measured renders"), help.toString());
    }

    @Test
    void badOptionsAreUsageErrors() throws IOException {
        Path scene = write("spheres.yaml", SPHERES);
        assertOneLine(converge(scene.toString(), "--spp", "4,0"), 2, "--spp values must be 1 to 1048576, got 0");
        assertOneLine(converge(scene.toString(), "--time", "-1"), 2, "--time values must be positive seconds");
        assertOneLine(converge(scene.toString(), "--config", "sampler=poisson-disk"), 2, "unknown sampler 'poisson-disk'; allowed: regular");
        assertOneLine(converge(scene.toString(), "--reference", "ref.png"), 2, "--reference must be auto, closed-form, self or a .pfm");
        assertOneLine(converge(scene.toString(), "--filter", "mitchell"), 2, "unknown --filter 'mitchell'; allowed: box, gaussian");
        assertOneLine(converge(scene.toString(), "--metric", "log"), 2, "--metric must be linear or srgb, got 'log'");
        // the exact images are box-filtered: the Gaussian cannot be measured against them
        assertOneLine(converge(Path.of("scenes", "closed-form-rectangle.yaml").toString(), "--filter", "gaussian", "--reference",
                               "closed-form", "-W", "8", "-H", "8", "--plot", dir.resolve("g.png").toString()),
                      1, "the exact image is of box-filtered pixels, and this run's filter is gaussian");
        // an output that cannot be written is a bad option value, as for render -o
        assertOneLine(converge(scene.toString(), "--plot", dir.resolve("p.jpg").toString()), 2, "give a name ending in .png");
        assertOneLine(converge(dir.resolve("missing.yaml").toString()), 1, "no such file");
        assertOneLine(converge(), 2, "Missing required parameter: 'SCENE'");
    }

    private static void assertOneLine(Result r, int code, String fragment) {
        assertEquals(code, r.code(), r.err());
        assertEquals(1, r.lines().length, r.err());
        assertTrue(r.err().contains(fragment), "'" + fragment + "' missing from: " + r.err());
        assertFalse(r.err().contains("\tat "), r.err());
    }
}

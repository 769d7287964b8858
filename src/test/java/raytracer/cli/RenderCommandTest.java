package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

public class RenderCommandTest {
    @TempDir
    Path dir;

    /** Exit code and everything written to stderr. */
    public record Result(int code, String err) {
        public String[] lines() {
            return err.strip().isEmpty() ? new String[0] : err.strip().split("\\R");
        }
    }

    public static Result run(String... args) {
        StringWriter err = new StringWriter();
        int code = RenderCommand.run(new PrintWriter(err, true), args);
        return new Result(code, err.toString());
    }

    private Path scene(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    private static final String SMALL = """
        image: {width: 16, height: 8, samples: 1}
        lights:
          - {type: point, position: [0, 5, 5], intensity: 40}
        objects:
          - {type: sphere, center: [0, 0.5, 0], radius: 0.5}
        """;

    /** A failure is one readable line on stderr, in one format whatever the exit code, without a stack trace. */
    private static void assertOneLineError(Result r, String... fragments) {
        assertTrue(r.code() != 0, "exit code should be non-zero");
        assertEquals(1, r.lines().length, "expected one line, got:\n" + r.err());
        assertTrue(r.err().startsWith("render: error: "), r.err());
        for (String f : fragments) {
            assertTrue(r.err().contains(f), "'" + f + "' missing from: " + r.err());
        }
        assertFalse(r.err().contains("\tat "), "stack trace printed without --verbose");
    }

    /** An 8-bit sRGB code for linear radiance, from IEC 61966-2-1, written out independently here. */
    private static int srgbCode(double linear) {
        double v = Math.max(0, Math.min(1, linear));
        double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
        return (int) Math.round(255 * encoded);
    }

    @Test
    void defaultSceneRendersToAPngThatEncodesItsLinearImage() throws IOException {
        Path png = dir.resolve("default.png");
        Path pfm = dir.resolve("default.pfm");
        Result r = run("-o", png.toString(), "-W", "96", "-H", "54", "--spp", "1");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("96x54") && r.err().contains("rays/s"), "summary line: " + r.err());
        assertEquals(0, run("-o", pfm.toString(), "-W", "96", "-H", "54", "--spp", "1", "-q").code());
        BufferedImage image = ImageIO.read(png.toFile());
        Film film = ImageWriters.readPfm(pfm);
        assertEquals(96, image.getWidth());
        assertEquals(54, image.getHeight());
        // every PNG code is the sRGB encoding of the same render's linear value
        for (int y = 0; y < 54; y++) {
            for (int x = 0; x < 96; x++) {
                int rgb = image.getRGB(x, y);
                int[] codes = {rgb >> 16 & 0xff, rgb >> 8 & 0xff, rgb & 0xff};
                for (int c = 0; c < 3; c++) {
                    assertEquals(srgbCode(film.get(x, y, c)), codes[c], "pixel " + x + ", " + y + ", channel " + c);
                }
            }
        }
        // the top row looks above the horizon at the scene's background; the bottom row sees the lit floor
        double[] sky = {0.52, 0.66, 0.85};
        int skyRgb = srgbCode(sky[0]) << 16 | srgbCode(sky[1]) << 8 | srgbCode(sky[2]);
        int floorPixels = 0;
        for (int x = 0; x < 96; x++) {
            assertEquals(skyRgb, image.getRGB(x, 0) & 0xffffff, "sky at " + x);
            floorPixels += (image.getRGB(x, 53) & 0xffffff) != skyRgb && film.get(x, 53, 0) > 0.1 ? 1 : 0;
        }
        assertEquals(96, floorPixels, "floor along the bottom row");
    }

    @Test
    void pfmOutputHoldsLinearRadiance() throws IOException {
        // a matte wall facing the camera, lit by a point light at the eye: through the centre pixel
        // L = ka La cd + kd cd / pi * I / r^2 = (0.2 * 0.1 + 0.8 * 25 pi / pi / 25) cd = 0.82 cd
        Path out = dir.resolve("linear.pfm");
        Path s = scene("wall.yaml", """
            image: {width: 3, height: 3, samples: 1, sampler: regular}
            camera: {eye: [0, 0, 5], look-at: [0, 0, 0], fov: 30}
            ambient: {radiance: 0.1}
            materials:
              wall: {type: matte, ka: 0.2, kd: 0.8, color: [0.5, 0.25, 1]}
            lights:
              - {type: point, position: [0, 0, 5], intensity: 78.53981633974483}
            objects:
              - {type: plane, point: [0, 0, 0], normal: [0, 0, 1], material: wall}
            """);
        Result r = run(s.toString(), "-o", out.toString(), "-q");
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err(), "--quiet prints nothing");
        Film film = ImageWriters.readPfm(out);
        assertEquals(3, film.width());
        assertEquals(3, film.height());
        assertEquals(0.82 * 0.5, film.get(1, 1, 0), 1e-6);
        assertEquals(0.82 * 0.25, film.get(1, 1, 1), 1e-6);
        assertEquals(0.82 * 1, film.get(1, 1, 2), 1e-6);
        // off-centre the wall is farther and slanted: darker, but still linear in the colour
        assertTrue(film.get(0, 0, 2) < film.get(1, 1, 2));
        assertEquals(0.5, film.get(0, 0, 0) / film.get(0, 0, 2), 1e-6);
    }

    @Test
    void sameImageBytesForOneTwoAndFourThreads() throws IOException {
        byte[][] images = new byte[3][];
        int[] threads = {1, 2, 4};
        for (int i = 0; i < 3; i++) {
            Path out = dir.resolve("t" + threads[i] + ".png");
            Result r = run("-o", out.toString(), "-W", "120", "-H", "70", "--spp", "4", "-t", String.valueOf(threads[i]), "-q");
            assertEquals(0, r.code(), r.err());
            images[i] = Files.readAllBytes(out);
        }
        assertArrayEquals(images[0], images[1]);
        assertArrayEquals(images[0], images[2]);
        Path other = dir.resolve("seed2.png");
        assertEquals(0, run("-o", other.toString(), "-W", "120", "-H", "70", "--spp", "4", "--seed", "2", "-q").code());
        assertFalse(java.util.Arrays.equals(images[0], Files.readAllBytes(other)), "the seed must matter");
    }

    @Test
    void bvhCostViewOfTheBunnyIsBrightestOnTheBunny() throws IOException {
        Path bunny = raytracer.io.obj.TestAssets.path("meshes/stanford-bunny.obj.gz").toAbsolutePath();
        Path s = scene("bunny.yaml", "image: {width: 64, height: 64, samples: 1}\n"
            + "camera: {eye: [-0.017, 0.11, 0.25], look-at: [-0.017, 0.11, 0], fov: 40}\n"
            + "objects:\n  - {type: mesh, file: " + bunny + "}\n");
        Path out = dir.resolve("cost.png");
        Result r = run(s.toString(), "-o", out.toString(), "--view", "bvh-cost", "--stats");
        assertEquals(0, r.code(), r.err());
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("bvh-cost: (\\d+) to (\\d+) bounding-volume tests").matcher(r.err());
        assertTrue(m.find(), r.err());
        int min = Integer.parseInt(m.group(1));
        int max = Integer.parseInt(m.group(2));
        assertTrue(min >= 1 && max > 20 * min, "range " + min + ".." + max);
        BufferedImage image = ImageIO.read(out.toFile());
        int centre = image.getRGB(32, 32) & 0xff;
        int corner = image.getRGB(1, 1) & 0xff;
        assertTrue(centre > corner + 50, "centre " + centre + " should be brighter than corner " + corner);
        assertTrue(r.err().contains("bounding-volume tests (BVH node boxes examined) per ray") && r.err().contains("peak heap"), r.err());
        // the counts are per pixel: a Gaussian filter, from the option or the scene, does not blur them
        Path gaussian = dir.resolve("cost-gaussian.png");
        Result g = run(s.toString(), "-o", gaussian.toString(), "--view", "bvh-cost", "--filter", "gaussian");
        assertEquals(0, g.code(), g.err());
        assertTrue(g.err().contains("bvh-cost: " + min + " to " + max + " bounding-volume tests"), g.err());
        assertArrayEquals(Files.readAllBytes(out), Files.readAllBytes(gaussian));
    }

    @Test
    void statsCountEveryRayByKind() throws IOException {
        // a wall filling the view, lit from in front: one shadow ray due per primary ray, which the
        // scene analysis leaves out and counts (nothing can come between a lone plane and its light);
        // a mirror wall adds one reflected ray per primary ray, which escapes and needs no shadow ray
        for (String material : new String[] {"matte", "reflective"}) {
            Path s = scene(material + ".yaml", "image: {width: 20, height: 10, samples: 4}\n"
                + "camera: {eye: [0, 0, 5], look-at: [0, 0, 0], fov: 40}\n"
                + "lights:\n  - {type: point, position: [0, 0, 3], intensity: 10}\n"
                + "materials:\n  m: {type: " + material + "}\n"
                + "objects:\n  - {type: plane, point: [0, 0, -2], normal: [0, 0, 1], material: m}\n");
            Result r = run(s.toString(), "-o", dir.resolve(material + ".png").toString(), "--stats", "--spp", "3");
            assertEquals(0, r.code(), r.err());
            java.util.regex.Matcher m = java.util.regex.Pattern
                .compile("stats: rays (\\d+) \\(primary (\\d+), shadow (\\d+), secondary (\\d+)\\), ([0-9.]+) M rays/s").matcher(r.err());
            assertTrue(m.find(), r.err());
            long primary = 20 * 10 * 4; // the default sampler rounds 3 samples up to a square, 4
            assertTrue(r.err().contains("20x10, 4 spp"), "the summary names the samples really taken: " + r.err());
            long secondary = material.equals("reflective") ? primary : 0;
            assertEquals(primary, Long.parseLong(m.group(2)), "primary, " + material);
            assertEquals(0, Long.parseLong(m.group(3)), "shadow, " + material);
            assertTrue(r.err().contains("stats: skip: no shadow rays towards light 1 (point light): no object can come "
                                        + "between it and a point it lights (saves " + primary + " shadow rays)"), r.err());
            assertEquals(secondary, Long.parseLong(m.group(4)), "secondary, " + material);
            assertEquals(primary + secondary, Long.parseLong(m.group(1)), "total, " + material);
            assertTrue(Double.parseDouble(m.group(5)) > 0, r.err());
            assertTrue(r.err().contains("stats: load scene") && r.err().matches("(?s).*render \\d+\\.\\d{3} s.*"), r.err());
            assertTrue(r.err().contains("prepare (objects in a list)"), "one plane needs no BVH: " + r.err());
            assertTrue(r.err().matches("(?s).*stats: [0-9.]+ bounding-volume tests \\(BVH node boxes examined\\) per ray, peak heap [1-9]\\d* MiB.*"), r.err());
        }
    }

    @Test
    void theSpotSceneRendersFromTheRepositoryAlone() throws IOException {
        // scenes/spot-cow.yaml reads assets/spot: a quad mesh, its .obj.mtl and map_Kd texture
        Path out = dir.resolve("spot.png");
        Result r = run("scenes/spot-cow.yaml", "-o", out.toString(), "-W", "80", "-H", "60", "--spp", "1");
        assertEquals(0, r.code(), r.err());
        assertFalse(r.err().toLowerCase(java.util.Locale.ROOT).contains("warning"), r.err());
        BufferedImage image = ImageIO.read(out.toFile());
        int brown = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y);
                int red = rgb >> 16 & 0xff;
                int blue = rgb & 0xff;
                brown += red >= blue + 15 ? 1 : 0; // the neutral floor reaches 10 at most
            }
        }
        // the grey floor, the blue sky and an untextured white cow have none; the muzzle and horns do
        assertTrue(brown > 40, "pixels of the texture's brown: " + brown);
    }

    @Test
    void bvhCostRangeIsPerRayWhateverTheSamplesAndRepeatsAreLabelled() throws IOException {
        StringBuilder spheres = new StringBuilder("image: {width: 48, height: 32, samples: 1}\nobjects:\n");
        for (int i = 0; i < 40; i++) {
            spheres.append("  - {type: sphere, center: [").append(i % 8 - 3.5).append(", ").append(i / 8 - 2)
                   .append(", 0], radius: 0.4}\n");
        }
        Path s = scene("spheres.yaml", spheres.toString());
        double[] max = new double[2];
        String[] spp = {"1", "4"};
        for (int k = 0; k < 2; k++) {
            Result r = run(s.toString(), "-o", dir.resolve("c" + k + ".png").toString(), "--view", "bvh-cost", "--spp", spp[k],
                           "--stats", "--repeat", "2", "-q");
            assertEquals(0, r.code(), r.err());
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("bvh-cost: ([0-9.]+) to ([0-9.]+) bounding-volume tests").matcher(r.err());
            assertTrue(m.find(), "the legend is printed even with -q: " + r.err());
            max[k] = Double.parseDouble(m.group(2));
            assertTrue(r.err().contains("render 1 of 2:") && r.err().contains("render 2 of 2:"), r.err());
            assertTrue(r.err().contains("prepare (top-level BVH)"), r.err());
        }
        // 40 spheres need a handful of box tests per ray, averaged over 1 or 4 samples alike
        assertTrue(max[0] > 5, "range with 1 sample: " + max[0]);
        assertTrue(max[1] > 0.5 * max[0] && max[1] <= max[0], "range with 4 samples: " + max[1] + " against " + max[0]);
    }

    @Test
    void anEmptySceneRendersWithAWarning() throws IOException {
        // it rendered a blank image without a word
        Path s = scene("empty.yaml", "image: {width: 4, height: 4, samples: 1}\nbackground: [0.2, 0.3, 0.4]\nobjects: []\n");
        Result r = run(s.toString(), "-o", dir.resolve("empty.png").toString());
        assertEquals(0, r.code(), r.err());
        assertEquals("render: warning: " + s + ":3:10: the scene has no objects; the image shows only the background",
                     r.lines()[0]);
        Result quiet = run(s.toString(), "-o", dir.resolve("empty.png").toString(), "-q");
        assertEquals("", quiet.err(), "--quiet hides warnings");
    }

    @Test
    void missingSceneFile() {
        assertOneLineError(run(dir.resolve("nope.yaml").toString(), "-o", dir.resolve("a.png").toString()), "nope.yaml");
    }

    @Test
    void syntaxErrorNamesFileLineAndColumn() throws IOException {
        Path s = scene("broken.yaml", "objects:\n  - {type: sphere, radius: [1, 2\n");
        assertOneLineError(run(s.toString(), "-o", dir.resolve("a.png").toString()), "broken.yaml:");
    }

    @Test
    void unknownKeyIsNamedWithTheAllowedOnes() throws IOException {
        Path s = scene("typo.yaml", SMALL + "  - {type: sphere, center: [0, 0, 0], radus: 1}\n");
        assertOneLineError(run(s.toString(), "-o", dir.resolve("a.png").toString()), "typo.yaml:6:", "radus", "radius");
    }

    @Test
    void negativeRadius() throws IOException {
        Path s = scene("neg.yaml", SMALL + "  - {type: sphere, center: [0, 0, 0], radius: -1}\n");
        assertOneLineError(run(s.toString(), "-o", dir.resolve("a.png").toString()), "neg.yaml:6:", "radius");
    }

    @Test
    void nanValue() throws IOException {
        Path s = scene("nan.yaml", SMALL + "  - {type: sphere, center: [0, .nan, 0], radius: 1}\n");
        assertOneLineError(run(s.toString(), "-o", dir.resolve("a.png").toString()), "nan.yaml:6:");
    }

    @Test
    void undefinedMaterial() throws IOException {
        Path s = scene("mat.yaml", SMALL + "  - {type: sphere, center: [0, 0, 0], radius: 1, material: gold}\n");
        assertOneLineError(run(s.toString(), "-o", dir.resolve("a.png").toString()), "mat.yaml:6:", "gold");
    }

    @Test
    void zeroSizeImageInTheScene() throws IOException {
        Path s = scene("zero.yaml", SMALL.replace("width: 16", "width: 0"));
        assertOneLineError(run(s.toString(), "-o", dir.resolve("a.png").toString()), "zero.yaml:1:");
    }

    @Test
    void theSamplerOptionReplacesTheScenesAndRoundsTheCountForIt() throws IOException {
        // the scene asks for multi-jittered, which rounds 3 samples up to 4; Sobol' takes 3 as they are
        // (a count the scene's sampler rounded stays rounded: --spp gives it anew)
        Path s = scene("sampler.yaml", "image: {width: 8, height: 6, samples: 3, sampler: multi-jittered}\n"
            + "camera: {eye: [0, 0, 5], look-at: [0, 0, 0], fov: 40}\n"
            + "lights:\n  - {type: rectangle, corner: [-1, 1, 3], edge-a: [2, 0, 0], edge-b: [0, -2, 0], radiance: 3, samples: 2, visible: false}\n"
            + "materials:\n  m: {type: matte}\n"
            + "objects:\n  - {type: plane, point: [0, 0, -2], normal: [0, 0, 1], material: m}\n");
        Result scenes = run(s.toString(), "-o", dir.resolve("mj.pfm").toString());
        assertTrue(scenes.err().contains("8x6, 4 spp"), scenes.err());
        Result sobol = run(s.toString(), "-o", dir.resolve("sobol.pfm").toString(), "--sampler", "sobol", "--spp", "3", "--stats");
        assertEquals(0, sobol.code(), sobol.err());
        // nothing can shadow the plane: the analysis counts the 48 x 3 x 2 shadow rays instead of tracing them
        assertTrue(sobol.err().contains("8x6, 3 spp") && sobol.err().contains("(144 primary")
                   && sobol.err().contains("saves 288 shadow rays"), sobol.err());
        assertFalse(Arrays.equals(Files.readAllBytes(dir.resolve("mj.pfm")), Files.readAllBytes(dir.resolve("sobol.pfm"))));
    }

    @Test
    void theFilterOptionReplacesTheScenesBoxWithTheGaussian() throws IOException {
        // a disk of radiance 1 (ambient only) on black, seen from above: the Gaussian spreads its
        // edge into the pixels around it, the box does not
        Path s = scene("filter.yaml", "image: {width: 24, height: 24, samples: 4, sampler: jittered}\n"
            + "tracer: ray-cast\nbackground: [0, 0, 0]\nambient: {radiance: 1}\n"
            + "camera: {type: orthographic, eye: [0, 5, 0], look-at: [0, 0, 0], up: [0, 0, -1], view-height: 24}\n"
            + "materials:\n  glow: {type: matte, ka: 1, kd: 0, color: [1, 1, 1]}\n"
            + "objects:\n  - {type: sphere, center: [0, 0, 0], radius: 6.2, material: glow}\n");
        Result box = run(s.toString(), "-o", dir.resolve("box.pfm").toString(), "--seed", "3");
        Result gaussian = run(s.toString(), "-o", dir.resolve("gaussian.pfm").toString(), "--filter", "gaussian", "--seed", "3");
        assertEquals(0, box.code(), box.err());
        assertEquals(0, gaussian.code(), gaussian.err());
        assertFalse(box.err().contains("filter"), "the book's box goes unmentioned: " + box.err());
        assertTrue(gaussian.err().contains(", gaussian filter of radius 2.0 pixels"), "the summary names the filter: " + gaussian.err());
        Result wide = run(s.toString(), "-o", dir.resolve("wide.pfm").toString(), "--filter-stddev", "1");
        assertEquals(0, wide.code(), wide.err());
        assertTrue(wide.err().contains(", gaussian filter of radius 4.0 pixels"), wide.err());
        Result both = run(s.toString(), "-o", dir.resolve("both.pfm").toString(), "--filter", "box", "--filter-stddev", "1");
        assertEquals(2, both.code(), both.err());
        assertTrue(both.err().contains("--filter-stddev is for --filter gaussian, not box"), both.err());
        Film b = ImageWriters.readPfm(dir.resolve("box.pfm"));
        Film g = ImageWriters.readPfm(dir.resolve("gaussian.pfm"));
        // along the middle row: the last lit pixel, then the first black one under the box
        int x = 12;
        while (b.get(x, 12, 0) > 0) {
            x++;
        }
        assertTrue(x > 15 && x < 20, "the disk's edge, radius 6.2 pixels from the centre: " + x);
        assertEquals(0, b.get(x, 12, 0), "box: outside the disk");
        assertTrue(g.get(x, 12, 0) > 0.005 && g.get(x, 12, 0) < 0.5, "Gaussian: light spills over the edge: " + g.get(x, 12, 0));
        assertEquals(0, g.get(x + 3, 12, 0), 1e-6, "Gaussian: nothing beyond its radius of 2 pixels");
        assertEquals(1, b.get(12, 12, 0), 1e-6, "box: the centre");
        assertEquals(1, g.get(12, 12, 0), 1e-6, "Gaussian: the centre, every sample around it lit");
    }

    @Test
    void outOfRangeOptions() {
        String out = dir.resolve("a.png").toString();
        // every bad option value is a usage error: exit code 2 and a pointer to --help
        String[][] cases = {
            {"--width", "0"}, {"--height", "-3"}, {"--spp", "0"}, {"--threads", "0"}, {"--threads", "32768"}, {"--max-depth", "-1"}, {"--max-depth", "100000"},
            {"--repeat", "0"}, {"--cutoff", "-1"}, {"--cutoff", "1"}, {"--spp", "many"}, {"--view", "x-ray"},
            {"--accel", "kd-tree"}, {"--encoding", "gamma"}, {"--pass", "glow"}, {"--sampler", "poisson-disk"}, {"--frobnicate", "1"},
            {"--filter", "mitchell"}, {"--filter-stddev", "3"},
        };
        for (String[] c : cases) {
            Result r = run("-o", out, c[0], c[1]);
            assertOneLineError(r, c[0].equals("--frobnicate") ? "frobnicate" : c[0].equals("--spp") && c[1].equals("many") ? "many" : c[1]);
            assertEquals(2, r.code(), String.join(" ", c) + ": " + r.err());
            assertTrue(r.err().contains("(see render --help)"), r.err());
        }
        // a fork/join pool runs at most 32767 threads; the message gives the range
        assertOneLineError(run("-o", out, "--threads", "2147483647"), "--threads must be 1 to 32767, got 2147483647");
        assertOneLineError(run("-o", out, "--max-depth", "1001"), "--max-depth must be 0 to 1000, got 1001");
        Result huge = run("-o", out, "--width", "50000", "--height", "50000");
        assertOneLineError(huge, "2500000000 pixels", "more than one image holds");
        assertEquals(2, huge.code());
        assertFalse(Files.exists(dir.resolve("a.png")), "nothing written");
    }

    @Test
    void unwritableOutputFailsBeforeRendering() throws IOException {
        Path file = Files.writeString(dir.resolve("plain.txt"), "x");
        assertOneLineError(run("-o", file.resolve("out.png").toString()), "does not exist");
        assertOneLineError(run("-o", dir.resolve("missing/out.png").toString()), "does not exist");
        // a bad -o is a bad option value like any other: exit code 2 and a pointer to --help
        for (Result r : new Result[] {run("-o", dir.resolve("out.jpg").toString()), run("-o", dir.toString())}) {
            assertOneLineError(r, r.err().contains("jpg") ? "unsupported extension" : "it is a directory", ".png", "(see render --help)");
            assertEquals(2, r.code(), r.err());
        }
    }

    @Test
    void aRenderThatFailsWhileWritingLeavesTheExistingImageUntouched() throws IOException, InterruptedException {
        // a render in its own process whose file size limit (ulimit -f, in KiB) stops the PNG after
        // 4 KiB: the write fails with "File too large" once the temporary file exists and is half
        // written, every time
        Path out = dir.resolve("good.png");
        byte[] good = {1, 2, 3};
        Files.write(out, good);
        Path javaCommand = Path.of(System.getProperty("java.home"), "bin", "java");
        Process child = new ProcessBuilder("bash", "-c", "ulimit -f 4 && exec \"$0\" \"$@\"", javaCommand.toString(),
                                           "-cp", System.getProperty("java.class.path"), RenderCommand.class.getName(),
                                           "-o", out.toString(), "-W", "200", "-H", "200", "--spp", "1", "-q")
            .redirectErrorStream(true).start();
        String err = new String(child.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertEquals(1, child.waitFor(), err);
        assertEquals("render: error: cannot write " + out + ": File too large", err);
        assertArrayEquals(good, Files.readAllBytes(out));
        try (var files = Files.list(dir)) {
            assertEquals(java.util.List.of(out), files.toList(), "no temporary file left");
        }
    }

    @Test
    void verboseAddsTheStackTrace() throws IOException {
        Result r = run(dir.resolve("nope.yaml").toString(), "-o", dir.resolve("a.png").toString(), "--verbose");
        assertTrue(r.code() != 0);
        assertTrue(r.err().contains("\tat "), r.err());
    }

    @Test
    void helpAndVersion() {
        // each in its own buffer: the version check passed on the help text before
        StringWriter help = new StringWriter();
        picocli.CommandLine cli = new picocli.CommandLine(new RenderCommand());
        cli.setOut(new PrintWriter(help, true));
        assertEquals(0, cli.execute("--help"));
        assertTrue(help.toString().startsWith("Usage: render ") && help.toString().contains("--max-depth"), help.toString());
        StringWriter version = new StringWriter();
        cli.setOut(new PrintWriter(version, true));
        assertEquals(0, cli.execute("--version"));
        assertTrue(version.toString().strip().matches("render (\\S+|\\(development build\\)) on Java " + java.util.regex.Pattern.quote(System.getProperty("java.version"))),
                   version.toString());
    }
}

package raytracer.cli.show;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cli.ErrorReport;

/**
 * {@code render --show} on a real X display: two Xvfb servers (one 640 x 480, one 200 x 150, too
 * small for a 320 x 240 image), each render in a JVM of its own ({@link ShowCapture}) that reads
 * the window's pixels back from the server once the render is done and then presses Esc. The window
 * shows exactly the PNG's pixels, or their reduction where the image is larger than the screen; Esc
 * or the close button during the render exits as SIGINT does and keeps the earlier file. Skipped,
 * saying why, only where Xvfb is not installed ({@code tools/ci/ensure-xvfb} installs it). On a
 * mismatch the capture, the file's pixels and their difference are left in build/show-window-test.
 */
class ShowWindowTest {
    private static final Path FAILURES = Path.of("build", "show-window-test");
    private static Process large;
    private static Process small;
    private static String largeDisplay;
    private static String smallDisplay;

    @TempDir
    Path dir;

    @BeforeAll
    static void startXvfb() throws Exception {
        String xvfb = onPath("Xvfb");
        Assumptions.assumeTrue(xvfb != null, "Xvfb is not installed, so --show cannot be tested on a display "
                                             + "(tools/ci/ensure-xvfb installs it: apt-get install xvfb)");
        Path log = Files.createTempFile("xvfb", ".log");
        log.toFile().deleteOnExit();
        large = startXvfb(xvfb, "640x480x24", log);
        largeDisplay = ":" + displayNumber(large, log);
        small = startXvfb(xvfb, "200x150x24", log);
        smallDisplay = ":" + displayNumber(small, log);
    }

    /** A server on a free display (-displayfd: Xvfb picks it), its messages in {@code log} so that it never blocks on them. */
    private static Process startXvfb(String xvfb, String screen, Path log) throws IOException {
        return new ProcessBuilder(xvfb, "-displayfd", "1", "-screen", "0", screen, "-nolisten", "tcp")
            .redirectError(ProcessBuilder.Redirect.appendTo(log.toFile())).start();
    }

    @AfterAll
    static void stopXvfb() {
        for (Process p : new Process[] {large, small}) {
            if (p != null) {
                p.destroy();
            }
        }
    }

    private static String onPath(String program) {
        for (String folder : System.getenv().getOrDefault("PATH", "/usr/bin").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(folder, program))) {
                return Path.of(folder, program).toString();
            }
        }
        return Files.isExecutable(Path.of("/usr/bin", program)) ? "/usr/bin/" + program : null;
    }

    /** The display Xvfb chose (-displayfd writes it once the server accepts clients). */
    private static String displayNumber(Process xvfb, Path log) throws Exception {
        CompletableFuture<String> line = CompletableFuture.supplyAsync(() -> {
            try {
                return new BufferedReader(new InputStreamReader(xvfb.getInputStream(), StandardCharsets.US_ASCII)).readLine();
            } catch (IOException e) {
                return null;
            }
        });
        String number = line.get(20, TimeUnit.SECONDS);
        if (number == null || !number.strip().matches("\\d+")) {
            xvfb.destroyForcibly();
            fail("Xvfb did not start (exit " + xvfb.waitFor() + "): " + Files.readString(log));
        }
        return number.strip();
    }

    /** Exit status and stderr of ShowCapture MODE FILE ARGS... on {@code display}. */
    private record Run(int status, String err) {
    }

    private Run capture(String display, String mode, Path file, String... renderArgs) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                                                       "-cp", System.getProperty("java.class.path"), ShowCapture.class.getName(),
                                                       mode, file == null ? "-" : file.toString()));
        command.addAll(Arrays.asList(renderArgs));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().put("DISPLAY", display);
        Process child = builder.start();
        CompletableFuture<String> err = CompletableFuture.supplyAsync(() -> {
            try {
                return new String(child.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                return e.toString();
            }
        });
        // longer than ShowCapture's own waits together (the window, then its paint), so that it reports first
        if (!child.waitFor(180, TimeUnit.SECONDS)) {
            child.destroyForcibly();
            fail("the window's JVM did not end: " + err.getNow(""));
        }
        Run run = new Run(child.exitValue(), err.get(10, TimeUnit.SECONDS));
        // when the screen stayed unpainted and the window's own painting was compared, the log says so
        run.err().lines().filter(line -> line.startsWith("show-capture:")).forEach(line -> System.out.println(file + ": " + line));
        return run;
    }

    private static int[] pixels(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xffffff;
        }
        return rgb;
    }

    /** Asserts the capture equals {@code expected} (width x height), leaving both and their difference for a human on failure. */
    private void assertShows(int[] expected, int width, int height, Path capture, String name) throws IOException {
        BufferedImage shot = ImageIO.read(capture.toFile());
        assertEquals(width + "x" + height, shot.getWidth() + "x" + shot.getHeight(), "the window's picture size");
        int[] shown = pixels(capture);
        int differing = 0;
        BufferedImage difference = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        BufferedImage reference = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int i = 0; i < expected.length; i++) {
            int d = 0;
            for (int shift = 0; shift < 24; shift += 8) {
                d |= Math.min(255, 8 * Math.abs((expected[i] >> shift & 0xff) - (shown[i] >> shift & 0xff))) << shift;
            }
            differing += d != 0 ? 1 : 0;
            difference.setRGB(i % width, i / width, d);
            reference.setRGB(i % width, i / width, expected[i]);
        }
        if (differing > 0) {
            Files.createDirectories(FAILURES);
            Files.copy(capture, FAILURES.resolve(name + "-window.png"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            ImageIO.write(reference, "png", FAILURES.resolve(name + "-file.png").toFile());
            ImageIO.write(difference, "png", FAILURES.resolve(name + "-difference.png").toFile());
            fail(differing + " of " + expected.length + " pixels differ between the window and the file; see " + FAILURES);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"shaded", "gaussian-linear", "bvh-cost"})
    void theWindowShowsThePngsPixels(String kind) throws Exception {
        Path out = dir.resolve(kind + ".png");
        Path shot = dir.resolve(kind + "-window.png");
        List<String> args = new ArrayList<>(List.of("-o", out.toString(), "-W", "160", "-H", "100", "--spp", "4", "--show"));
        switch (kind) {
            case "gaussian-linear" -> args.addAll(List.of("--filter", "gaussian", "--encoding", "linear"));
            case "bvh-cost" -> args.addAll(List.of("--view", "bvh-cost"));
            default -> { }
        }
        Run run = capture(largeDisplay, "capture", shot, args.toArray(String[]::new));
        assertEquals(0, run.status(), "Esc after the render closes the window and the run ends well: " + run.err());
        assertShows(pixels(out), 160, 100, shot, kind);
    }

    /** With --frames the window shows each frame in turn, in the one film, and ends on the last frame's file. */
    @Test
    void theFramesOfAnAnimationEndOnTheLastFrame() throws Exception {
        Path scene = Files.writeString(dir.resolve("spin.yaml"), """
            image: {width: 96, height: 64, samples: 4}
            lights:
              - {type: point, position: [2, 6, 4], intensity: 60}
            objects:
              - {type: plane, normal: [0, 1, 0]}
              - {type: box, name: crate, min: [-0.5, 0, -0.5], max: [0.5, 1, 0.5]}
            animation: {frames: 3, objects: {crate: {keys: [{frame: 0, rotate-y: 0}, {frame: 3, rotate-y: 90}]}}}
            """);
        Path shot = dir.resolve("frames-window.png");
        Run run = capture(largeDisplay, "capture", shot, scene.toString(), "--frames", "0-2", "-o", dir.resolve("f-%d.png").toString(),
                          "--show");
        assertEquals(0, run.status(), run.err());
        assertTrue(run.err().contains("frames 0-2 of " + scene + ": 3 rendered"), run.err());
        assertShows(pixels(dir.resolve("f-2.png")), 96, 64, shot, "frames");
    }

    @Test
    void anImageLargerThanTheScreenIsShownReduced() throws Exception {
        Path out = dir.resolve("large.png");
        Path shot = dir.resolve("large-window.png");
        Run run = capture(smallDisplay, "capture", shot, "-o", out.toString(), "-W", "320", "-H", "240", "--spp", "1", "--show");
        assertEquals(0, run.status(), run.err());
        int[] reduced = new int[200 * 150];
        ShowScale.reduce(pixels(out), 320, 240, reduced, 200, 150, 0, 0, 320, 240);
        assertShows(reduced, 200, 150, shot, "large");
    }

    @ParameterizedTest
    @ValueSource(strings = {"escape", "close"})
    void cancellingMidRenderKeepsTheEarlierFile(String how) throws Exception {
        Path out = dir.resolve("earlier.png");
        byte[] earlier = "an earlier render".getBytes(StandardCharsets.US_ASCII);
        Files.write(out, earlier);
        // a render of minutes on one thread: the window is cancelled at its first repaint
        Run run = capture(largeDisplay, how, null, "-o", out.toString(), "-W", "320", "-H", "240", "--spp", "4096", "-t", "1",
                          "--show");
        assertEquals(ErrorReport.INTERRUPTED, run.status(), "exit status as for SIGINT: " + run.err());
        assertTrue(run.err().contains("render: cancelled from the window; " + out + " left as it was"), run.err());
        assertArrayEquals(earlier, Files.readAllBytes(out), "the earlier file is kept");
        try (var files = Files.list(dir)) {
            assertEquals(List.of(out), files.toList(), "nothing but the earlier file (no .partial)");
        }
    }
}

package raytracer.cli.show;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.ErrorReport;
import raytracer.cli.RenderCommand;

/**
 * {@code --show} where no window can open, and runs without it, each in a JVM of its own (whose
 * environment and loaded classes this one cannot be mistaken for): without a display the option is
 * one line and status 2 before any work; without the option no AWT class is loaded, as the JVM's
 * class-load log shows (the same log lists AWT's classes once --show asks for a display).
 */
class ShowWithoutDisplayTest {
    @TempDir
    Path dir;

    /** Exit status, stdout (the class-load log) and stderr of {@code render ARGS} run with {@code jvmArgs} and {@code env}. */
    private record Run(int status, String out, String err) {
        List<String> errLines() {
            return err.isBlank() ? List.of() : Arrays.asList(err.strip().split("\\R"));
        }

        /** The classes the JVM loaded whose names start with one of {@code prefixes}. */
        List<String> loaded(String... prefixes) {
            List<String> found = new ArrayList<>();
            for (String line : out.split("\\R")) {
                // [0.360s][info][class,load] java.awt.Toolkit source: jrt:/java.desktop
                int at = line.indexOf("[class,load] ");
                if (at >= 0) {
                    String name = line.substring(at + 13).split(" ")[0];
                    if (Arrays.stream(prefixes).anyMatch(name::startsWith)) {
                        found.add(name);
                    }
                }
            }
            return found;
        }
    }

    private static Run render(Map<String, String> env, List<String> jvmArgs, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(jvmArgs);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), RenderCommand.class.getName()));
        command.addAll(Arrays.asList(args));
        ProcessBuilder builder = new ProcessBuilder(command);
        builder.environment().remove("DISPLAY");
        builder.environment().remove("WAYLAND_DISPLAY");
        builder.environment().putAll(env);
        Process child = builder.start();
        CompletableFuture<String> out = CompletableFuture.supplyAsync(() -> text(child.getInputStream()));
        CompletableFuture<String> err = CompletableFuture.supplyAsync(() -> text(child.getErrorStream()));
        if (!child.waitFor(60, TimeUnit.SECONDS)) {
            child.destroyForcibly().waitFor();
            throw new AssertionError("render did not end within 60 s; stderr: " + err.get());
        }
        return new Run(child.exitValue(), out.get(), err.get());
    }

    private static String text(java.io.InputStream in) {
        try {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return e.toString();
        }
    }

    /** A display number that no X server holds here (none has its socket or lock file). */
    private static String deadDisplay() {
        for (int n = 4321; ; n++) {
            if (!Files.exists(Path.of("/tmp/.X11-unix/X" + n)) && !Files.exists(Path.of("/tmp/.X" + n + "-lock"))) {
                return ":" + n;
            }
        }
    }

    @Test
    void withoutADisplayShowIsOneLineAndStatusTwoBeforeAnyWork() throws Exception {
        // the scene file does not exist: its error would come first if the scene were read first
        Path scene = dir.resolve("not-read.yaml");
        Path out = dir.resolve("out.png");
        Object[][] cases = {
            {Map.of(), List.of(), "DISPLAY is not set"},
            {Map.of("DISPLAY", deadDisplay()), List.of(), "cannot connect to the display DISPLAY=:"},
            {Map.of("DISPLAY", deadDisplay()), List.of("-Djava.awt.headless=true"), "headless"},
        };
        for (Object[] c : cases) {
            @SuppressWarnings("unchecked")
            Run run = render((Map<String, String>) c[0], (List<String>) c[1], scene.toString(), "-o", out.toString(), "--show");
            String why = c[0] + " " + c[1] + ": " + run.err();
            assertEquals(ErrorReport.BAD_USAGE, run.status(), why);
            assertEquals(1, run.errLines().size(), why);
            assertTrue(run.err().startsWith("render: error: --show needs a graphical display: " ), why);
            assertTrue(run.err().contains((String) c[2]), why);
            assertFalse(Files.exists(out), why);
        }
    }

    /**
     * A display that accepts the connection and never answers (a stalled X server, a dead ssh -X
     * forward): the check is bounded ({@link GraphicalDisplay#ANSWER_SECONDS}) and fails with the
     * one line. Before, render blocked for ever before any work, silent.
     */
    @Test
    void aDisplayThatNeverAnswersIsOneLineAndStatusTwo() throws Exception {
        try (ServerSocket silent = bindDisplayPort()) {
            int display = silent.getLocalPort() - 6000;
            Path out = dir.resolve("out.png");
            Run run = render(Map.of("DISPLAY", "127.0.0.1:" + display), List.of(), "-o", out.toString(), "--show");
            String why = run.err();
            assertEquals(ErrorReport.BAD_USAGE, run.status(), why);
            assertEquals(List.of("render: error: --show needs a graphical display: the display DISPLAY=127.0.0.1:" + display
                                 + " did not answer in " + GraphicalDisplay.ANSWER_SECONDS
                                 + " s (a stalled X server or a dead ssh -X forward?) (see render --help)"), run.errLines());
            assertFalse(Files.exists(out), why);
        }
    }

    /** A loopback port of an X display (6000 + n) that takes connections into its backlog and never answers them. */
    private static ServerSocket bindDisplayPort() throws IOException {
        for (int n = 4321; n < 4400; n++) {
            try {
                return new ServerSocket(6000 + n, 50, InetAddress.getLoopbackAddress());
            } catch (BindException taken) {
                // try the next
            }
        }
        throw new IOException("no free display port from 6000 + 4321 to 6000 + 4399");
    }

    @Test
    void withoutShowNoAwtClassIsLoaded() throws Exception {
        String[] awt = {"java.awt.", "javax.swing.", "sun.awt.", "sun.java2d.", "javax.imageio.", "raytracer.cli.show."};
        List<String> log = List.of("-Xlog:class+load=info:stdout");
        for (String view : new String[] {"shaded", "bvh-cost"}) {
            Path out = dir.resolve(view + ".png");
            Run run = render(Map.of("DISPLAY", deadDisplay()), log, "-o", out.toString(), "-W", "48", "-H", "32", "--spp", "1",
                             "--view", view, "--filter", view.equals("shaded") ? "gaussian" : "box", "-q");
            assertEquals(0, run.status(), run.err());
            assertTrue(Files.exists(out));
            assertTrue(run.loaded("raytracer.cli.").contains("raytracer.cli.render.RenderRun"), "the log lists the run's classes");
            assertEquals(List.of(), run.loaded(awt), view);
        }
        // the log would show AWT: --show loads it to look for a display
        Run shown = render(Map.of(), log, "-o", dir.resolve("x.png").toString(), "--show");
        assertEquals(ErrorReport.BAD_USAGE, shown.status(), shown.err());
        assertTrue(shown.loaded("java.awt.").contains("java.awt.GraphicsEnvironment"), "AWT in the log with --show");
    }
}

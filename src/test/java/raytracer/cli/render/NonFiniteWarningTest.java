package raytracer.cli.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.RenderCommandTest;
import raytracer.cli.RenderCommandTest.Result;
import raytracer.image.Film;
import raytracer.render.NonFiniteScene;
import raytracer.render.RenderStats;
import raytracer.render.Renders;

/**
 * Dropped samples are a warning line of their own, which --quiet keeps: before,
 * the only sign was ", WARNING: 540 non-finite samples dropped" at the end of the summary line,
 * which -q hides, and the MTL values that caused them rendered with exit 0.
 */
class NonFiniteWarningTest {
    @TempDir
    Path dir;

    @Test
    void droppedSamplesAreAWarningLineOfTheirOwn() {
        RenderStats stats = Renders.render(NonFiniteScene.world(), 2, 1, new Film(NonFiniteScene.W, NonFiniteScene.H));
        assertEquals(NonFiniteScene.NON_FINITE_SAMPLES, stats.nonFiniteSamples());
        StringWriter err = new StringWriter();
        new RunReport(new PrintWriter(err, true), 1).droppedSamples(stats);
        assertEquals("render: warning: " + NonFiniteScene.NON_FINITE_SAMPLES + " non-finite samples (NaN or infinite radiance) "
                     + "dropped; the pixels they fell in average the others", err.toString().strip());
        assertFalse(RunReport.summaryLine(stats, Path.of("out.png")).contains("WARNING"));
    }

    @Test
    void noWarningWithoutDroppedSamples() {
        RenderStats clean = new RenderStats(16, 8, 4, 2, 1_000_000, 512, 0, 0, 0, 0);
        String line = RunReport.summaryLine(clean, Path.of("out.png"));
        assertTrue(line.startsWith("out.png: 16x8, 4 spp, 2 threads"), line);
        StringWriter err = new StringWriter();
        new RunReport(new PrintWriter(err, true), 1).droppedSamples(clean);
        assertEquals("", err.toString());
    }

    /** The MTL values that made non-finite samples are refused at load, with file and line, even with -q. */
    @Test
    void anInfiniteMtlColourIsAnErrorNotASilentBlackObject() throws IOException {
        Files.writeString(dir.resolve("t.mtl"), "newmtl a\nKd 1e400 1 1\n");
        Files.writeString(dir.resolve("t.obj"), "mtllib t.mtl\nusemtl a\nv -1 0 -1\nv 1 0 -1\nv 0 0 1\nf 1 3 2\n");
        Path scene = Files.writeString(dir.resolve("s.yaml"), """
            image: {width: 8, height: 8, samples: 1}
            camera: {eye: [0, 1, 3], look-at: [0, 0, 0]}
            lights:
              - {type: point, position: [0, 3, 0], intensity: 1}
            objects:
              - {type: mesh, file: t.obj}
            """);
        Result r = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("o.png").toString(), "-q", "--no-cache");
        assertEquals(1, r.code(), r.err());
        assertTrue(r.err().contains("t.mtl:2: Kd must be 3 finite numbers of at least 0, got 1e400"), r.err());
    }
}

package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import raytracer.image.Film;
import raytracer.render.NonFiniteScene;
import raytracer.render.RenderStats;
import raytracer.render.Renders;

/** The summary line that the command prints after a render warns when samples were dropped, with their count. */
class NonFiniteWarningTest {

    @Test
    void summaryWarnsOfDroppedSamples() {
        RenderStats stats = Renders.render(NonFiniteScene.world(), 2, 1, new Film(NonFiniteScene.W, NonFiniteScene.H));
        assertEquals(NonFiniteScene.NON_FINITE_SAMPLES, stats.nonFiniteSamples());
        String line = RunReport.summaryLine(stats, Path.of("out.png"));
        assertTrue(line.endsWith(", WARNING: " + NonFiniteScene.NON_FINITE_SAMPLES + " non-finite samples dropped"), line);
    }

    @Test
    void noWarningWithoutDroppedSamples() {
        RenderStats clean = new RenderStats(16, 8, 4, 2, 1_000_000, 512, 0, 0, 0, 0);
        String line = RunReport.summaryLine(clean, Path.of("out.png"));
        assertTrue(line.startsWith("out.png: 16x8, 4 spp, 2 threads"), line);
        assertFalse(line.contains("WARNING"), line);
    }
}

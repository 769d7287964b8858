package raytracer.cli.converge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.api.Scene;
import raytracer.api.SceneFrame;
import raytracer.api.SceneOptions;
import raytracer.image.ErrorMetrics;
import raytracer.render.Renders;
import raytracer.render.Workers;

/** A self-rendered reference measures its own noise truly: checked against the exact image of a closed-form scene. */
class ConvergeReferenceTest {

    @Test
    void theHalvesDifferenceEstimatesTheReferencesTrueError() throws Exception {
        Path file = Path.of("scenes", "closed-form-disk.yaml");
        ConvergeReference.Image ref;
        try (Workers workers = new Workers(2)) {
            SceneFrame frame = Scene.open(file, SceneOptions.NONE.withSize(24, 24)).load(0, workers);
            frame.prepare(workers);
            ref = ConvergeReference.rendered(file, Files.readAllBytes(file), frame, 128, 5, null,
                (world, rayTree, seed, film, label) -> Renders.render(world, rayTree, 2, seed, film), new PrintWriter(new StringWriter()));
        }
        var exact = ConvergeReference.closedForm(file, 24, 24, new PrintWriter(new StringWriter()), true).get();
        double trueRmse = ErrorMetrics.compare(ref.film(), 1, exact.film()).rmse();
        // 576 pixels: the two estimates of one variance agree to about 10%
        assertEquals(trueRmse, ref.noiseRmse(), 0.2 * trueRmse, "estimated " + ref.noiseRmse() + ", true " + trueRmse);
        assertEquals(0, exact.noiseRmse(), 0);
    }

    @Test
    void aReferenceThatIsAFifoIsNotARegularFile(@TempDir Path dir) throws Exception {
        Path fifo = dir.resolve("ref.pfm");
        assertEquals(0, new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor());
        IOException e = assertThrows(IOException.class, () -> ConvergeReference.fromFile(fifo, 4, 4));
        assertTrue(e.getMessage().contains("not a regular file (it is a FIFO"), e.getMessage());
    }
}

package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.RenderCommandTest.Result;
import raytracer.core.Sampler;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;

/**
 * Sample counts near 2^31 used to overflow when rounded up to a square: --spp
 * 2147483647 reported -2147479015 samples, a light or glossy material of 2147483647 samples took 0
 * and vanished, converge printed a negative count and exited 0. Every count is bounded where it is
 * read, and the message gives the limit.
 */
class SampleCountLimitTest {
    @TempDir
    Path dir;

    private static final String LIMIT = "1 to " + Sampler.MAX_SAMPLES;

    private static final String SCENE = """
        image: {width: 4, height: 4, samples: 1}
        lights:
          - {type: rectangle, corner: [-1, 3, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], samples: 1}
        objects:
          - {type: sphere, center: [0, 0.5, 0], radius: 0.5}
        """;

    @Test
    void theLimitIsASquareThatRoundingKeeps() {
        int side = (int) Math.sqrt(Sampler.MAX_SAMPLES);
        assertEquals(Sampler.MAX_SAMPLES, side * side, "square patterns round the largest count to itself");
        assertEquals(Sampler.MAX_SAMPLES, raytracer.samplers.Samplers.byName("multi-jittered").supportedCount(Sampler.MAX_SAMPLES));
    }

    @Test
    void theCommandLineBoundsEveryCount() throws IOException {
        Path scene = Files.writeString(dir.resolve("s.yaml"), SCENE);
        Result r = RenderCommandTest.run(scene.toString(), "--spp", "2147483647", "-o", dir.resolve("a.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--spp must be " + LIMIT + ", got 2147483647"), r.err());
        r = RenderCommandTest.run("converge", scene.toString(), "--spp", "2147483647", "--plot", dir.resolve("p.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--spp values must be " + LIMIT + ", got 2147483647"), r.err());
        r = RenderCommandTest.run("converge", scene.toString(), "--spp", "1", "--config", "light-samples=2147483647", "--plot",
                                  dir.resolve("p.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("light-samples must be " + LIMIT + ", got 2147483647"), r.err());
        r = RenderCommandTest.run("converge", scene.toString(), "--spp", "1", "--reference-spp", "2147483647", "--plot",
                                  dir.resolve("p.png").toString());
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--reference-spp must be 1 to " + 2 * Sampler.MAX_SAMPLES), r.err());
    }

    private void assertRefused(String text, String fragment) throws IOException {
        Path scene = Files.writeString(dir.resolve("s.yaml"), text);
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(scene));
        assertTrue(e.getMessage().contains(fragment), e.getMessage());
        assertTrue(e.getMessage().matches(".*s\\.yaml:\\d+:\\d+: .*"), "file:line:column: " + e.getMessage());
    }

    @Test
    void theSceneFileBoundsEveryCount() throws IOException {
        String most = "must be at most " + Sampler.MAX_SAMPLES + ", got 2147483647";
        assertRefused(SCENE.replace("samples: 1}\nlights", "samples: 2147483647}\nlights"), "'samples' in image " + most);
        assertRefused(SCENE.replace("samples: 1}\nobjects", "samples: 2147483647}\nobjects"), "'samples' in rectangle light " + most);
        assertRefused(SCENE.replace("objects:", "materials:\n  g: {type: glossy, samples: 2147483647}\nobjects:"),
                "'samples' in glossy material 'g' " + most);
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.core.Light;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.samplers.MultiJittered;
import raytracer.samplers.PureRandom;

/** The overrides the convergence benchmark applies after a scene is read: area-light samples and the sampler. */
class SceneOverridesTest {
    @TempDir
    Path dir;

    @Test
    void everyAreaLightTakesTheOverridingSampleCount() throws Exception {
        Path file = dir.resolve("s.yaml");
        Files.writeString(file, """
            lights:
              - {type: rectangle, corner: [0, 2, 0], edge-a: [1, 0, 0], edge-b: [0, 0, 1], samples: 4}
              - {type: disk, center: [0, 2, 0], normal: [0, -1, 0]}
              - {type: point, position: [0, 2, 0]}
            objects:
              - {type: plane, normal: [0, 1, 0]}
            """);
        World scene = SceneLoader.load(file).world();
        scene.prepare();
        assertEquals(4, scene.lights()[0].sampleCount());
        assertEquals(LightReader.AREA_SAMPLES, scene.lights()[1].sampleCount());
        World overridden = SceneLoader.load(file, OptionalInt.of(9)).world();
        overridden.prepare();
        Light[] lights = overridden.lights();
        assertEquals(9, lights[0].sampleCount());
        assertEquals(9, lights[1].sampleCount());
        assertEquals(1, lights[2].sampleCount(), "a point light has one sample whatever the override");
    }

    @Test
    void anotherSamplerRoundsTheSampleCountForItself() {
        ViewPlane random = new ViewPlane(8, 8, 5, new PureRandom(), 2, 1);
        assertEquals(5, random.numSamples());
        ViewPlane square = random.withSampler(new MultiJittered());
        assertEquals(9, square.numSamples(), "multi-jittered patterns are squares");
        assertEquals(MultiJittered.class, square.sampler().getClass());
    }
}

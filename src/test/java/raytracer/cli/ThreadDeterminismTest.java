package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same scene and seed give the same linear image, byte for byte, for any number of threads,
 * where random numbers matter most: area lights sampled per hit, glossy rays, glass that splits,
 * a thin lens. Tiles finish in any order, so any randomness not drawn from the pixel's own seed
 * would show here.
 */
class ThreadDeterminismTest {
    @TempDir
    Path dir;

    private static final String SCENE = """
        image: {width: 40, height: 30, samples: 4, max-depth: 4}
        camera: {type: thin-lens, eye: [0, 1.5, 6], look-at: [0, 0.8, 0], fov: 45, lens-radius: 0.05}
        materials:
          floor: {type: matte, texture: {type: checker, size: 0.5}}
          glossy: {type: glossy, color: [0.8, 0.5, 0.3], ks: 0.6, exponent: 40, samples: 4}
          glass: {type: dielectric, ior: 1.5, absorption: [0.2, 0.05, 0.1]}
        lights:
          - {type: rectangle, corner: [-1, 3, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], radiance: 6, samples: 4}
          - {type: sphere, center: [2.5, 2, 1], radius: 0.3, radiance: 20, samples: 4}
          - {type: point, position: [-3, 4, 3], intensity: 20}
        objects:
          - {type: plane, normal: [0, 1, 0], material: floor}
          - {type: sphere, center: [-0.9, 0.7, 0], radius: 0.7, material: glossy}
          - {type: sphere, center: [0.9, 0.7, 0.5], radius: 0.7, material: glass}
        """;

    private byte[] render(Path scene, String threads, String seed) throws IOException {
        Path out = dir.resolve("t" + threads + "s" + seed + ".pfm");
        StringWriter err = new StringWriter();
        int code = RenderCommand.run(new PrintWriter(err, true), scene.toString(), "-o", out.toString(), "-t", threads,
                                     "--seed", seed, "-q");
        assertEquals(0, code, err.toString());
        return Files.readAllBytes(out);
    }

    @Test
    void oneTwoAndThreeThreadsGiveTheSamePfm() throws IOException {
        Path scene = Files.writeString(dir.resolve("mix.yaml"), SCENE);
        byte[] one = render(scene, "1", "5");
        assertArrayEquals(one, render(scene, "2", "5"), "2 threads");
        assertArrayEquals(one, render(scene, "3", "5"), "3 threads");
        assertFalse(Arrays.equals(one, render(scene, "2", "6")), "the seed must matter");
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.RGBColor;

/**
 * What a light emits (its scale times its colour) must fit the image's float channels: 1e308 x 1e308
 * rendered +Inf pixels without a word. Such a scene is refused, naming the keys and the limit.
 */
class EmissionLimitTest {
    private static final String OBJECTS = "objects:\n  - {type: sphere, center: [0, 0, 0]}\n";

    private static String error(String text) {
        return assertThrows(SceneException.class, () -> SceneLoader.load("s.yaml", text)).getMessage();
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        point light       | lights: [{type: point, position: [0, 5, 0], intensity: 1e308, color: [1e308, 1e308, 1e308]}] | s.yaml:1:56: 'intensity' x 'color' in point light must be at most 3.40282e+38 (the largest value an image holds), got 1.00000e+308 x 1.00000e+308
        point, alone      | lights: [{type: point, position: [0, 5, 0], intensity: 1e300}]                               | s.yaml:1:56: 'intensity' x 'color' in point light must be at most 3.40282e+38 (the largest value an image holds), got 1.00000e+300 x 1.00000
        colour alone      | lights: [{type: point, position: [0, 5, 0], color: [0, 4e38, 0]}]                            | s.yaml:1:52: 'intensity' x 'color' in point light must be at most 3.40282e+38 (the largest value an image holds), got 1.00000 x 4.00000e+38
        directional light | lights: [{type: directional, direction: [0, 1, 0], radiance: 1e20, color: [1, 1e19, 1]}]      | s.yaml:1:62: 'radiance' x 'color' in directional light must be at most 3.40282e+38 (the largest value an image holds), got 1.00000e+20 x 1.00000e+19
        area light        | lights: [{type: sphere, center: [0, 5, 0], radiance: 1e39}]                                  | s.yaml:1:54: 'radiance' x 'color' in sphere light must be at most 3.40282e+38 (the largest value an image holds), got 1.00000e+39 x 1.00000
        ambient           | ambient: {radiance: 2e38, color: [2, 2, 2]}                                                  | s.yaml:1:21: 'radiance' x 'color' in ambient must be at most 3.40282e+38 (the largest value an image holds), got 2.00000e+38 x 2.00000
        """)
    void emissionBeyondWhatAnImageHoldsIsRefused(String what, String section, String message) {
        assertEquals(message, error(section + "\n" + OBJECTS));
    }

    @Test
    void emissionUpToTheLimitLoads() throws SceneException {
        World world = SceneLoader.load("s.yaml", "ambient: {radiance: 1e38, color: [3.4, 0, 1]}\n"
            + "lights: [{type: point, position: [0, 5, 0], intensity: 3.4e38}, {type: point, position: [0, 5, 0], intensity: 1e300, color: [1e-262, 0, 0]}]\n"
            + OBJECTS).world();
        // both lights kept, and the products as given: the check refuses, it never clamps
        assertEquals(2, world.lightList().size());
        RGBColor ambient = ((Ambient) world.ambient()).radiance();
        assertEquals(3.4e38, ambient.r(), 3.4e38 * 1e-15);
        assertEquals(1e38, ambient.b(), 1e38 * 1e-15);
    }

    @Test
    void anEnvironmentMapTimesItsIntensityIsChecked(@TempDir Path dir) throws IOException, SceneException {
        // one Radiance texel of mantissa 255 and exponent 255: (255 + 0.5) 2^(255 - 136) = 1.698e38
        byte[] header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n".getBytes(StandardCharsets.US_ASCII);
        byte[] file = java.util.Arrays.copyOf(header, header.length + 4);
        file[header.length] = (byte) 255;
        file[header.length + 3] = (byte) 255;
        Files.write(dir.resolve("bright.hdr"), file);
        Files.writeString(dir.resolve("ok.yaml"), "environment: {file: bright.hdr, intensity: 1.5}\n" + OBJECTS);
        SceneLoader.load(dir.resolve("ok.yaml"));
        Files.writeString(dir.resolve("s.yaml"), "environment: {file: bright.hdr, intensity: 3}\n" + OBJECTS);
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("s.yaml")));
        assertEquals(dir.resolve("s.yaml") + ":1:44: 'intensity' x the brightest pixel of " + dir.resolve("bright.hdr")
                     + " in environment must be at most 3.40282e+38 (the largest value an image holds), got 3.00000 x 1.69809e+38",
                     e.getMessage());
    }
}

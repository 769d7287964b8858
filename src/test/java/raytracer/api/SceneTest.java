package raytracer.api;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.filters.Gaussian;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.SceneException;
import raytracer.render.Workers;

/**
 * The one place a scene file and options become a scene: its image settings are known before
 * anything is loaded (a missing mesh is found only when a frame loads), a frame's world has them,
 * and a render through the API is the command line's, byte for byte.
 */
class SceneTest {
    @TempDir
    Path dir;

    @Test
    void imageSettingsAreReadWithoutLoadingAMesh() throws Exception {
        Path file = Files.writeString(dir.resolve("s.yaml"), """
            image: {width: 64, height: 48, samples: 4, exposure: 2, encoding: linear}
            objects:
              - {type: mesh, file: nowhere.obj}
            animation: {frames: 9, fps: 12}
            """);
        Scene scene = Scene.open(file, SceneOptions.NONE.withSize(20, 10).withFilter("gaussian", 0.7));
        ImageSettings image = scene.image();
        assertEquals(20, image.width());
        assertEquals(10, image.height());
        assertEquals(4, image.viewPlane().numSamples());
        assertEquals(0.7, ((Gaussian) image.filter()).stddev());
        assertEquals(2, image.exposure());
        assertEquals(false, image.srgb());
        assertEquals(9, image.frames());
        assertEquals(12, image.fps());
        try (Workers workers = new Workers(1)) {
            SceneException e = assertThrows(SceneException.class, () -> scene.load(0, workers));
            assertTrue(e.getMessage().contains("nowhere.obj"), e.getMessage());
        }
    }

    @Test
    void aRenderThroughTheApiIsTheCommandLines() throws Exception {
        java.io.StringWriter err = new java.io.StringWriter();
        int code = raytracer.cli.RenderCommand.run(new java.io.PrintWriter(err, true), "scenes/turntable-bunny.yaml",
                                                   "-W", "40", "-H", "30", "--spp", "2", "--filter", "gaussian",
                                                   "--frames", "7", "-o", dir.resolve("cli-%d.pfm").toString(), "--no-cache", "-q");
        assertEquals(0, code, err.toString());
        Scene scene = Scene.open(Path.of("scenes/turntable-bunny.yaml"), SceneOptions.NONE.withSize(40, 30).withSamples(2)
            .withFilter("gaussian", null));
        Film film = new Film(40, 30);
        try (Workers workers = new Workers(2)) {
            SceneFrame frame = scene.load(7, workers);
            assertSame(scene.image().viewPlane(), frame.world().viewPlane(), "the frame renders the settings read before it");
            frame.prepare(workers);
            frame.renderer(workers).render(film);
        }
        Path api = dir.resolve("api.pfm");
        ImageWriters.write(film, scene.image().exposure(), scene.image().srgb(), api);
        assertArrayEquals(Files.readAllBytes(dir.resolve("cli-7.pfm")), Files.readAllBytes(api));
    }
}

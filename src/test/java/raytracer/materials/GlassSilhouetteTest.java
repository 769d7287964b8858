package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;
import raytracer.render.RenderStats;
import raytracer.render.Renders;

/**
 * Glass up to its silhouette. A camera ray tangent to an absorbing sphere touches it without
 * entering; taken as a hit on the back face, it was darkened by Beer's law over its whole way from
 * the camera, (0.082, 0.0067, 4.5e-5) where the background shows 1.
 */
class GlassSilhouetteTest {
    /** The regular sampler's one sample per pixel lies at the pixel centre, x and y in {-1, -0.5, 0, 0.5, 1}. */
    private static final String SCENE = """
        image: {width: 5, height: 5, samples: 1, sampler: regular, max-depth: 5}
        background: [1, 1, 1]
        camera: {type: orthographic, eye: [0, 0, 5], look-at: [0, 0, 0], view-height: 2.5}
        ambient: {radiance: 0}
        materials:
          glass: {type: dielectric, ior: 1.0, absorption: [0.5, 1, 2]}
        objects:
          - {type: sphere, center: [0, 0, 0], radius: 1, material: glass}
        """;

    @Test
    void aSphereOfIndexOneShowsBeersLawOverItsChordsAndTheBackgroundAtItsSilhouette() throws SceneException {
        LoadedScene scene = SceneLoader.load("silhouette.yaml", SCENE);
        World world = scene.world();
        world.prepare();
        Film film = new Film(5, 5);
        RenderStats stats = Renders.render(world, scene.rayTree(), 1, 1, film);
        assertEquals(0, stats.nonFiniteSamples());
        double[] absorption = {0.5, 1, 2};
        for (int row = 0; row < 5; row++) {
            for (int column = 0; column < 5; column++) {
                double x = 0.5 * column - 1;
                double y = 1 - 0.5 * row;
                // index 1 bends nothing and reflects nothing: the ray crosses along the chord
                double chord = 2 * Math.sqrt(Math.max(0, 1 - x * x - y * y));
                for (int c = 0; c < 3; c++) {
                    double expected = Math.exp(-absorption[c] * chord);
                    assertEquals(expected, film.get(column, row, c), 1e-6 * expected,
                                 "pixel (" + x + ", " + y + "), channel " + c);
                }
            }
        }
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.render.Renders;

/**
 * A glossy material as a user writes it, without {@code normalized}, reflects its surroundings at
 * the strength of a mirror of the same ks: under a white sky (the background, radiance 1, no
 * lights), the point of a glossy sphere facing the camera reflects ks cs times the integral of the
 * normalised lobe's cos(theta_i), which for exponent e is ks (e + 2) / (e + 1) E[cos(theta_i)],
 * within 1% of ks at e = 200 (the lobe stays within 10 degrees of the normal). The report's
 * unnormalised lobe reflected 2 pi / (e + 1) of that, 3%: a glossy sphere showed almost nothing.
 */
class GlossyDefaultTest {
    private static double centre(String material) throws SceneException {
        LoadedScene scene = SceneLoader.load("glossy.yaml", """
            image: {width: 1, height: 1, samples: 64, max-depth: 1}
            background: [1, 1, 1]
            ambient: {radiance: 0}
            camera: {eye: [0, 0, 5], look-at: [0, 0, 0], fov: 0.1}
            materials:
              m: %s
            objects:
              - {type: sphere, center: [0, 0, 0], radius: 1, material: m}
            """.formatted(material));
        World world = scene.world();
        world.prepare();
        Film film = new Film(1, 1);
        Renders.render(world, scene.rayTree(), 1, 1, film);
        return film.get(0, 0, 1);
    }

    @Test
    void theDefaultGlossyReflectsAsAMirrorOfTheSameKs() throws SceneException {
        double glossy = centre("{type: glossy, ka: 0, kd: 0, ks: 0.5, exponent: 200, samples: 16}");
        double mirror = centre("{type: reflective, ka: 0, kd: 0, ks: 0, kr: 0.5}");
        assertEquals(0.5, mirror, 1e-6, "the mirror reflects kr of the white sky");
        assertEquals(mirror, glossy, 0.01 * mirror, "the default glossy lobe reflects about ks");
        double report = centre("{type: glossy, ka: 0, kd: 0, ks: 0.5, exponent: 200, samples: 16, normalized: false}");
        assertEquals(0.5 * 2 * Math.PI / 201, report, 0.01 * report, "the report's lobe, when asked for");
    }
}

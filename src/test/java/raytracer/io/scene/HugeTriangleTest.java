package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cache.MeshCache;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.render.Renders;
import raytracer.shapes.Triangle;

/**
 * Triangles are bounded at load as spheres are: before, triangles of extent
 * about 1e77 to 1e153 rendered unlit with no shadow ray (their normal, the cross product of two
 * edges, squared past the largest double and normalised to 0), and from 1e154 were never hit, all
 * without a word. A coordinate past {@link Triangle#MAX_COORDINATE} is refused with its file and
 * line; up to it, a scene renders as it does at scale 1.
 */
class HugeTriangleTest {
    @TempDir
    Path dir;

    private static final String TRIANGLES = """
        image: {width: 16, height: 12, samples: 1}
        camera: {eye: [0, 1S, 3S], look-at: [0, 0, 0], fov: 40}
        ambient: {radiance: 0.1}
        lights:
          - {type: directional, direction: [0.3, 1, 0.5], radiance: 1}
        objects:
          - {type: triangle, vertices: [[-1S, 0, -1S], [1S, 0, -1S], [0, 0, 1S]]}
          - {type: mesh, file: tent.obj, smooth: true}
        """;

    /** A tent of four triangles at scale {@code s}, above the floor triangle. */
    private Path scene(String s) throws IOException {
        Files.writeString(dir.resolve("tent.obj"), ("v -0.5S 0.1S -0.5S\nv 0.5S 0.1S -0.5S\nv 0.5S 0.1S 0.5S\nv -0.5S 0.1S 0.5S\n"
                                                    + "v 0 0.6S 0\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n").replace("S", s));
        return Files.writeString(dir.resolve("s.yaml"), TRIANGLES.replace("S", s));
    }

    private byte[] image(Path scene) throws IOException, SceneException {
        World world = SceneLoader.load(scene, (MeshCache) null).world();
        world.prepare();
        Film film = new Film(16, 12);
        Renders.render(world, 1, 1, film);
        Path pfm = dir.resolve("i.pfm");
        ImageWriters.write(film, 1, pfm);
        return Files.readAllBytes(pfm);
    }

    @Test
    void upToTheLimitASceneOfTrianglesRendersAsAtScaleOne() throws IOException, SceneException {
        byte[] one = image(scene("e0"));
        assertArrayEquals(one, image(scene("e" + (int) Math.log10(Triangle.MAX_COORDINATE))));
    }

    @Test
    void pastTheLimitATriangleIsRefusedWithItsPlace() throws IOException {
        Path scene = scene("e77");
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(scene, (MeshCache) null));
        assertTrue(e.getMessage().startsWith(scene + ":7:5: triangle: "), e.getMessage());
        assertTrue(e.getMessage().contains("at most 1.0E75"), e.getMessage());
        Files.writeString(scene, TRIANGLES.replace("S", "e0"));
        Files.writeString(dir.resolve("tent.obj"), "v 0 0 0\nv 1e77 0 0\nv 0 1 0\nf 1 2 3\n");
        e = assertThrows(SceneException.class, () -> SceneLoader.load(scene, (MeshCache) null));
        assertTrue(e.getMessage().contains("tent.obj:2: coordinate '1e77' is larger than 1.0E75"), e.getMessage());
    }
}

package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.accel.MeshBVH;
import raytracer.cache.MeshCache;
import raytracer.core.GeometricObject;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.render.Renders;
import raytracer.shapes.Instance;

/**
 * Objects naming one OBJ file with the same options share one parse and one tree: before, every object held its own copy, so 400 references to a 40k-triangle file peaked at
 * 693 MiB and 1000 ran out of a 1 GiB heap. Objects that differ only by their transform are one
 * object, instanced; the image is the same as with a copy of the file per object.
 */
class SharedMeshTest {
    @TempDir
    Path dir;

    private static final String TENT = "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1 0\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";

    private Path scene(String... files) throws IOException {
        StringBuilder text = new StringBuilder("""
            image: {width: 24, height: 16, samples: 1}
            camera: {eye: [0, 4, 9], look-at: [0, 0, 0], fov: 50}
            lights:
              - {type: point, position: [2, 6, 4], intensity: 60}
            materials:
              red: {type: matte, color: [1, 0.2, 0.2]}
            objects:
            """);
        for (int i = 0; i < files.length; i++) {
            text.append("  - {type: mesh, file: ").append(files[i]).append(i == 3 ? ", material: red" : "")
                .append(", transform: [{rotate-y: ").append(17 * i).append("}, {translate: [").append(2.5 * i - 4).append(", 0, 0]}]}\n");
        }
        return Files.writeString(dir.resolve("s.yaml"), text);
    }

    private World prepared(Path scene, MeshCache cache) throws SceneException {
        World world = SceneLoader.load(scene, cache).world();
        world.prepare();
        return world;
    }

    private byte[] image(World world) throws IOException {
        Film film = new Film(24, 16);
        Renders.render(world, 1, 1, film);
        Path pfm = dir.resolve("i.pfm");
        ImageWriters.write(film, 1, pfm);
        return Files.readAllBytes(pfm);
    }

    private static MeshBVH mesh(GeometricObject object) {
        return (MeshBVH) ((Instance) object).object();
    }

    @Test
    void objectsNamingOneFileShareItsArraysAndTree() throws IOException, SceneException {
        Files.writeString(dir.resolve("tent.obj"), TENT);
        for (MeshCache cache : new MeshCache[] {null, MeshCache.in(dir.resolve("cache"), Long.MAX_VALUE, 0), MeshCache.in(dir.resolve("cache"), Long.MAX_VALUE, 0)}) {
            World world = prepared(scene("tent.obj", "tent.obj", "tent.obj", "tent.obj"), cache);
            List<GeometricObject> objects = world.objects();
            assertEquals(4, objects.size());
            assertSame(mesh(objects.get(0)), mesh(objects.get(1)), "objects that differ only by transform are one object");
            assertSame(mesh(objects.get(0)), mesh(objects.get(2)));
            MeshBVH red = mesh(objects.get(3));
            assertNotSame(mesh(objects.get(0)), red, "another material: another object...");
            assertSame(mesh(objects.get(0)).mesh(), red.mesh(), "...around the same arrays");
            assertSame(mesh(objects.get(0)).bvh(), red.bvh(), "...and the same tree");
        }
    }

    @Test
    void sharingChangesNoPixel() throws IOException, SceneException {
        for (String copy : new String[] {"a.obj", "b.obj", "c.obj", "d.obj"}) {
            Files.writeString(dir.resolve(copy), TENT);
        }
        byte[] copies = image(prepared(scene("a.obj", "b.obj", "c.obj", "d.obj"), null));
        byte[] shared = image(prepared(scene("a.obj", "a.obj", "a.obj", "a.obj"), null));
        assertArrayEquals(copies, shared);
        LoadReport report = SceneLoader.load(scene("a.obj", "a.obj", "a.obj", "a.obj"), (MeshCache) null).report();
        assertTrue(report.statistics().contains("mesh a.obj: 4 objects share one copy of it"), report.statistics().toString());
    }
}

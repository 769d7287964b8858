package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.image.Film;

/** Where references are kept, what their key depends on, and that a damaged file is not used. */
class ReferenceCacheTest {
    @TempDir
    Path dir;

    @Test
    void theFolderFollowsXdgElseHome() {
        assertEquals(Path.of("/x/raytracer/references"), ReferenceCache.defaultDir(Map.of("XDG_CACHE_HOME", "/x"), "/home/u"));
        assertEquals(Path.of("/home/u/.cache/raytracer/references"), ReferenceCache.defaultDir(Map.of(), "/home/u"));
        // the XDG specification ignores relative paths
        assertEquals(Path.of("/home/u/.cache/raytracer/references"), ReferenceCache.defaultDir(Map.of("XDG_CACHE_HOME", "rel"), "/home/u"));
    }

    @Test
    void theKeyChangesWithTheSceneAndEverySetting() {
        byte[] scene = "objects: []".getBytes(StandardCharsets.UTF_8);
        ReferenceCache cache = new ReferenceCache(dir);
        Path file = cache.file("my scene.yaml", scene, "spp=64\n");
        assertTrue(file.getFileName().toString().matches("my_scene-[0-9a-f]{16}\\.pfm"), file.toString());
        assertEquals(file, cache.file("my scene.yaml", scene.clone(), "spp=64\n"));
        assertNotEquals(file, cache.file("my scene.yaml", scene, "spp=65\n"));
        assertNotEquals(file, cache.file("my scene.yaml", "objects: [ ]".getBytes(StandardCharsets.UTF_8), "spp=64\n"));
    }

    @Test
    void storedReferencesComeBackAndDamagedOnesDoNot() throws IOException {
        ReferenceCache cache = new ReferenceCache(dir.resolve("a/b"));
        Path file = cache.file("s.yaml", new byte[0], "");
        assertTrue(cache.load(file).isEmpty());
        Film film = new Film(3, 2);
        film.set(2, 1, 0.5, 1, 2);
        assertTrue(cache.noise(file).isEmpty());
        cache.store(file, film, "what it is\n" + ReferenceCache.NOISE_KEY + "0.125\n");
        assertEquals(2, cache.load(file).get().get(2, 1, 2), 0);
        assertEquals(0.125, cache.noise(file).getAsDouble(), 0);
        Path text = file.resolveSibling(file.getFileName().toString().replace(".pfm", ".txt"));
        assertTrue(Files.readString(text).startsWith("what it is\n"));
        Files.writeString(text, ReferenceCache.NOISE_KEY + "lots\n");
        assertTrue(cache.noise(file).isEmpty(), "a damaged description counts as none");
        Files.write(file, new byte[] {'P', 'F', '\n'});
        assertTrue(cache.load(file).isEmpty(), "a damaged file is rendered again, not used");
    }
}

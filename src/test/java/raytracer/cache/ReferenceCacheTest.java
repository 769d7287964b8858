package raytracer.cache;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.image.Film;

/** Where references are kept, what their key depends on, that a damaged entry is not used, and that nothing else is touched. */
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
        assertTrue(file.getFileName().toString().matches("my_scene-[0-9a-f]{16}\\.ref"), file.toString());
        assertEquals(file, cache.file("my scene.yaml", scene.clone(), "spp=64\n"));
        assertNotEquals(file, cache.file("my scene.yaml", scene, "spp=65\n"));
        assertNotEquals(file, cache.file("my scene.yaml", "objects: [ ]".getBytes(StandardCharsets.UTF_8), "spp=64\n"));
        assertTrue(cache.file("x".repeat(300) + ".yaml", scene, "").getFileName().toString().length() < 100, "a long name is cut");
    }

    @Test
    void storedReferencesComeBackAndDamagedOnesDoNot() throws IOException {
        ReferenceCache cache = new ReferenceCache(dir.resolve("a/b"));
        Path file = cache.file("s.yaml", new byte[0], "");
        List<String> why = new ArrayList<>();
        assertTrue(cache.load(file, why::add).isEmpty());
        assertEquals(List.of(), why, "no entry: nothing to say");
        Film film = new Film(3, 2);
        film.set(2, 1, 0.5, 1, 2);
        cache.store(file, film, 0.125, "what it is\n");
        ReferenceCache.Reference back = cache.load(file, why::add).orElseThrow();
        assertEquals(2, back.film().get(2, 1, 2), 0);
        assertEquals(0.125, back.noiseRmse(), 0);
        assertTrue(new String(Files.readAllBytes(file), StandardCharsets.UTF_8).contains("what it is\nnoise-rmse=0.125\n"),
                   "the description is text a person can read in the entry");
        byte[] good = Files.readAllBytes(file);
        for (int at : new int[] {30, good.length - 1}) {
            byte[] damaged = good.clone();
            damaged[at] ^= 0x20;
            Files.write(file, damaged);
            assertTrue(cache.load(file, why::add).isEmpty(), "a damaged entry is rendered again, not used");
            assertEquals("does not match its checksum", why.remove(0));
        }
        byte[] newer = good.clone();
        newer[ReferenceCache.MAGIC_BYTES.length + 3]++;
        Files.write(file, newer);
        assertTrue(cache.load(file, why::add).isEmpty());
        assertEquals(List.of(), why, "an entry of another version is rendered again without a word");
        Files.write(file, new byte[] {'P', 'F', '\n'});
        assertTrue(cache.load(file, why::add).isEmpty());
        assertEquals(List.of("is not a reference of this program"), why);
    }

    /** Storing writes through a temporary file and removes a killed writer's stale one; the user's files stay as they are. */
    @Test
    void onlyItsOwnFilesAreTouched() throws IOException {
        ReferenceCache cache = new ReferenceCache(dir);
        Path file = cache.file("s.yaml", new byte[0], "");
        Path stale = Files.write(dir.resolve("." + file.getFileName() + ".k1.partial"), ReferenceCache.MAGIC_BYTES);
        Files.setLastModifiedTime(stale, FileTime.fromMillis(System.currentTimeMillis() - 2 * CacheFolder.STALE_PARTIAL.toMillis()));
        Path notes = Files.writeString(dir.resolve("notes.txt"), "the user's");
        Path lookalike = Files.writeString(dir.resolve("." + file.getFileName() + ".k2.partial"), "the user's, named as ours");
        Files.setLastModifiedTime(lookalike, FileTime.fromMillis(0));
        cache.store(file, new Film(2, 2), 0, "");
        assertFalse(Files.exists(stale), "a killed writer's temporary file, an hour old");
        assertEquals("the user's", Files.readString(notes));
        assertEquals("the user's, named as ours", Files.readString(lookalike));
        assertTrue(cache.load(file, why -> { }).isPresent());
    }
}

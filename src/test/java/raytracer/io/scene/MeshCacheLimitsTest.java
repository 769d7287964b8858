package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.core.World;

/**
 * The mesh cache as a good citizen (issue 25, item 12): before, it grew without bound, cached
 * meshes of 16 triangles, kept one entry per absolute path (the same files in 6 folders made 6
 * entries), never removed the entries of deleted OBJ files nor the .partial files of killed
 * writers, and could never cache a file whose name passed about 230 characters. Now it has a size
 * cap with least-recently-used eviction, skips meshes that parse about as fast as they are read,
 * keys entries by content, removes stale .partial files, and bounds its names.
 */
class MeshCacheLimitsTest {
    @TempDir
    Path dir;

    /** A grid of n x n quads (2 n^2 triangles) named {@code name}, in {@code folder}, with an MTL beside it. */
    private static Path grid(Path folder, String name, int n, double wave) throws IOException {
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("grid.mtl"), "newmtl a\nKd 0.8 0.3 0.2\n");
        StringBuilder obj = new StringBuilder("mtllib grid.mtl\nusemtl a\n");
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                double x = (double) i / n - 0.5;
                double z = (double) j / n - 0.5;
                obj.append("v ").append(x).append(' ').append(wave * Math.sin(7 * x + 3 * z)).append(' ').append(z).append('\n');
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1;
                obj.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + n + 2).append(' ').append(a + n + 1)
                   .append('\n');
            }
        }
        return Files.writeString(folder.resolve(name), obj);
    }

    private static LoadReport load(Path obj, MeshCache cache) throws IOException, SceneException {
        Path scene = Files.writeString(obj.resolveSibling("s.yaml"), "image: {width: 8, height: 6, samples: 1}\n"
            + "objects:\n  - {type: mesh, file: \"" + obj.getFileName() + "\"}\n");
        LoadedScene loaded = SceneLoader.load(scene, cache);
        World world = loaded.world();
        world.prepare();
        return loaded.report();
    }

    private static boolean readFromCache(LoadReport report) {
        return report.statistics().stream().anyMatch(s -> s.contains("read from the mesh cache"));
    }

    private List<Path> entries(Path cache) throws IOException {
        try (Stream<Path> files = Files.list(cache)) {
            return files.filter(p -> p.toString().endsWith(".mesh")).sorted().toList();
        }
    }

    @Test
    void theCapEvictsTheLeastRecentlyUsedEntries() throws Exception {
        Path cacheDir = dir.resolve("cache");
        Path a = grid(dir.resolve("a"), "a.obj", 20, 0.1);
        load(a, MeshCache.in(cacheDir, Long.MAX_VALUE, 0));
        long entry = Files.size(entries(cacheDir).get(0));
        // room for two entries of this size, not three
        MeshCache capped = MeshCache.in(cacheDir, 2 * entry + entry / 2, 0);
        Path b = grid(dir.resolve("b"), "b.obj", 20, 0.2);
        load(b, capped);
        assertEquals(2, entries(cacheDir).size());
        // a is used again, after b: b is now the least recently used
        Thread.sleep(20);
        assertTrue(readFromCache(load(a, capped)));
        Thread.sleep(20);
        Path c = grid(dir.resolve("c"), "c.obj", 20, 0.3);
        LoadReport third = load(c, capped);
        assertTrue(third.statistics().toString().contains("1 least recently used entry evicted"), third.statistics().toString());
        List<Path> left = entries(cacheDir);
        assertEquals(2, left.size(), left.toString());
        assertTrue(left.stream().anyMatch(p -> p.getFileName().toString().startsWith("a.obj-")), left.toString());
        assertTrue(left.stream().anyMatch(p -> p.getFileName().toString().startsWith("c.obj-")), left.toString());
        assertTrue(readFromCache(load(a, capped)));
        assertFalse(readFromCache(load(b, capped)), "b was evicted");
    }

    @Test
    void aMeshThatParsesAsFastAsItIsReadIsNotCached() throws Exception {
        Path small = grid(dir.resolve("s"), "small.obj", 4, 0.1);
        assertTrue(Files.size(small) < MeshCache.MIN_OBJ_BYTES);
        LoadReport report = load(small, MeshCache.in(dir.resolve("cache")));
        assertFalse(Files.exists(dir.resolve("cache")), "nothing written");
        assertTrue(report.statistics().toString().contains("not cached (smaller than " + MeshCache.MIN_OBJ_BYTES / 1024
                                                           + " KiB: parsed about as fast as read)"), report.statistics().toString());
        Path large = grid(dir.resolve("l"), "large.obj", 90, 0.1);
        assertTrue(Files.size(large) >= MeshCache.MIN_OBJ_BYTES, "size " + Files.size(large));
        load(large, MeshCache.in(dir.resolve("cache")));
        assertEquals(1, entries(dir.resolve("cache")).size());
    }

    @Test
    void copiesInOtherFoldersShareOneEntry() throws Exception {
        Path cacheDir = dir.resolve("cache");
        MeshCache cache = MeshCache.in(cacheDir, Long.MAX_VALUE, 0);
        Path first = grid(dir.resolve("one"), "m.obj", 10, 0.1);
        load(first, cache);
        for (String folder : List.of("two", "three", "four")) {
            Path copy = grid(dir.resolve(folder), "m.obj", 10, 0.1);
            assertTrue(readFromCache(load(copy, cache)), folder);
        }
        assertEquals(1, entries(cacheDir).size(), "one entry for four copies");
    }

    @Test
    void stalePartialFilesAreRemovedAndFreshOnesKept() throws Exception {
        Path cacheDir = Files.createDirectories(dir.resolve("cache"));
        Path stale = Files.writeString(cacheDir.resolve(".m.obj-0123456789abcdef.mesh.x1.partial"), "killed");
        Files.setLastModifiedTime(stale, FileTime.from(Instant.now().minus(2, ChronoUnit.HOURS)));
        Path fresh = Files.writeString(cacheDir.resolve(".m.obj-0123456789abcdef.mesh.x2.partial"), "being written");
        load(grid(dir.resolve("p"), "m.obj", 10, 0.1), MeshCache.in(cacheDir, Long.MAX_VALUE, 0));
        assertFalse(Files.exists(stale), "a writer's leftover more than an hour old");
        assertTrue(Files.exists(fresh), "another process may be writing this one");
    }

    @Test
    void aLongFileNameIsCachedUnderAShortName() throws Exception {
        String name = "x".repeat(240) + ".obj";
        Path obj = grid(dir.resolve("long"), name, 10, 0.1);
        MeshCache cache = MeshCache.in(dir.resolve("cache"), Long.MAX_VALUE, 0);
        LoadReport first = load(obj, cache);
        assertEquals(List.of(), first.warnings());
        assertTrue(readFromCache(load(obj, cache)));
        assertTrue(entries(dir.resolve("cache")).get(0).getFileName().toString().length() < 100);
    }

    @Test
    void sizesAreReadWithTheirUnits() {
        assertEquals(1L << 30, MeshCache.parseSize("1G"));
        assertEquals(512L << 20, MeshCache.parseSize("512M"));
        assertEquals(100L << 10, MeshCache.parseSize("100k"));
        assertEquals(12345, MeshCache.parseSize("12345"));
        assertEquals(0, MeshCache.parseSize("0"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MeshCache.parseSize("lots"));
        assertEquals("a size such as 512M or 2G is expected, got 'lots'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> MeshCache.parseSize("-1G"));
        assertThrows(IllegalArgumentException.class, () -> MeshCache.parseSize("99999999999G"));
    }
}

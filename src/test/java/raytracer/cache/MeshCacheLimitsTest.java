package raytracer.cache;

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
import raytracer.io.scene.LoadReport;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;

/**
 * The mesh cache as a good citizen: before, it grew without bound, cached meshes of 16 triangles,
 * kept one entry per absolute path (the same files in 6 folders made 6 entries), never removed
 * the entries of deleted OBJ files nor the .partial files of killed writers, and could never cache
 * a file whose name passed about 230 characters. Now it has a size
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
        Path stale = Files.writeString(cacheDir.resolve(".m.obj-0123456789abcdef.mesh.x1.partial"), "RTMESH\0\0 killed");
        Path empty = Files.writeString(cacheDir.resolve(".m.obj-0123456789abcdef.mesh.x3.partial"), "");
        for (Path old : List.of(stale, empty)) {
            Files.setLastModifiedTime(old, FileTime.from(Instant.now().minus(2, ChronoUnit.HOURS)));
        }
        Path fresh = Files.writeString(cacheDir.resolve(".m.obj-0123456789abcdef.mesh.x2.partial"), "RTMESH\0\0 being written");
        load(grid(dir.resolve("p"), "m.obj", 10, 0.1), MeshCache.in(cacheDir, Long.MAX_VALUE, 0));
        assertFalse(Files.exists(stale), "a writer's leftover more than an hour old");
        assertFalse(Files.exists(empty), "a writer killed before it wrote a byte");
        assertTrue(Files.exists(fresh), "another process may be writing this one");
    }

    /**
     * A --cache-dir may be a folder of the user's own (models/, say): eviction deleted every *.mesh
     * file in it and any .*.partial an hour old. The cache touches only files it can prove it
     * wrote: named as its entries and starting with its format's magic bytes.
     */
    @Test
    void evictionTouchesOnlyTheCachesOwnFiles() throws Exception {
        Path models = Files.createDirectories(dir.resolve("models"));
        Path old = dir.resolve("elsewhere.bin");
        Files.writeString(old, "the user's");
        List<Path> users = new java.util.ArrayList<>(List.of(
            Files.writeString(models.resolve("character.mesh"), "a mesh of another program"),
            Files.writeString(models.resolve("notes.txt"), "notes"),
            // named as an entry is, but not one: no magic bytes
            Files.writeString(models.resolve("rock.obj-0123456789abcdef.mesh"), "x".repeat(5000)),
            // a temporary name of an entry, an hour old, but not the cache's content
            Files.writeString(models.resolve(".rock.obj-0123456789abcdef.mesh.abc.partial"), "draft"),
            Files.writeString(models.resolve(".backup.partial"), "the user's draft")));
        users.add(Files.createSymbolicLink(models.resolve("tree.obj-fedcba9876543210.mesh"), old));
        for (Path p : users) {
            Files.setLastModifiedTime(p, FileTime.from(Instant.now().minus(3, ChronoUnit.HOURS)));
        }
        // an entry of the cache's own, least recently used
        Path a = grid(dir.resolve("a"), "a.obj", 20, 0.1);
        load(a, MeshCache.in(models, Long.MAX_VALUE, 0));
        Path first = entries(models).stream().filter(p -> p.getFileName().toString().startsWith("a.obj-")).findFirst().orElseThrow();
        Files.setLastModifiedTime(first, FileTime.from(Instant.now().minus(2, ChronoUnit.HOURS)));
        // a cap with room for one entry alone: everything else in the folder is over it (half as
        // much again as the first, since the SAH tree of the other grid may have more nodes)
        LoadReport second = load(grid(dir.resolve("b"), "b.obj", 20, 0.2), MeshCache.in(models, Files.size(first) * 3 / 2, 0));
        assertTrue(second.statistics().toString().contains("1 least recently used entry evicted"), second.statistics().toString());
        assertFalse(Files.exists(first), "the cache's own older entry is evicted");
        for (Path p : users) {
            assertTrue(Files.exists(p, java.nio.file.LinkOption.NOFOLLOW_LINKS), p + " is the user's and must stay");
        }
        assertEquals("the user's", Files.readString(old));
    }

    /**
     * Writers in several threads (or processes) storing at once, with a cap that holds two entries:
     * once all are done the cache is under its cap. Each writes and trims under the folder's lock;
     * without it two writers could each miss the other's entry in their listing.
     */
    @Test
    void concurrentWritersKeepTheCap() throws Exception {
        Path cacheDir = dir.resolve("cache");
        int writers = 6;
        List<Path> objs = new java.util.ArrayList<>();
        for (int i = 0; i < writers; i++) {
            objs.add(grid(dir.resolve("w" + i), "w" + i + ".obj", 12, 0.1 + i / 10.0));
        }
        load(objs.get(0), MeshCache.in(dir.resolve("probe"), Long.MAX_VALUE, 0));
        long entry;
        try (Stream<Path> files = Files.list(dir.resolve("probe"))) {
            entry = Files.size(files.filter(p -> p.toString().endsWith(".mesh")).findFirst().orElseThrow());
        }
        long cap = 2 * entry + entry / 2;
        for (int round = 0; round < 3; round++) {
            java.util.concurrent.CyclicBarrier start = new java.util.concurrent.CyclicBarrier(writers);
            List<Thread> threads = new java.util.ArrayList<>();
            List<Throwable> failures = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
            for (Path obj : objs) {
                Thread t = new Thread(() -> {
                    try {
                        start.await();
                        load(obj, MeshCache.in(cacheDir, cap, 0));
                    } catch (Throwable e) {
                        failures.add(e);
                    }
                });
                threads.add(t);
                t.start();
            }
            for (Thread t : threads) {
                t.join();
            }
            assertEquals(List.of(), failures);
            long total = 0;
            for (Path p : entries(cacheDir)) {
                total += Files.size(p);
            }
            assertTrue(total <= cap, "round " + round + ": " + total + " bytes in " + entries(cacheDir) + ", cap " + cap);
            // every mesh is written afresh next round
            for (Path p : entries(cacheDir)) {
                Files.delete(p);
            }
        }
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

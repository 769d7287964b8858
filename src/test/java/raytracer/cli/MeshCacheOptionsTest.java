package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** --cache-dir keeps meshes between runs and --stats says which way each came; --no-cache keeps none. */
class MeshCacheOptionsTest {
    @TempDir
    Path dir;

    private Path scene() throws IOException {
        // a quad, and enough copies of its face to be worth caching (MeshCache.MIN_OBJ_BYTES)
        Files.writeString(dir.resolve("quad.obj"), "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n" + "f 1 2 3 4\n".repeat(25_000));
        return Files.writeString(dir.resolve("s.yaml"), "image: {width: 8, height: 6, samples: 1}\n"
            + "camera: {eye: [0, 2, 3], look-at: [0, 0, 0], fov: 50}\n"
            + "lights:\n  - {type: point, position: [0, 2, 1], intensity: 5}\n"
            + "objects:\n  - {type: mesh, file: quad.obj}\n");
    }

    @Test
    void theSecondRunReadsTheCache() throws IOException {
        Path scene = scene();
        String cache = dir.resolve("meshes").toString();
        RenderCommandTest.Result first = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("1.pfm").toString(),
                                                               "--stats", "--cache-dir", cache);
        assertEquals(0, first.code(), first.err());
        assertTrue(first.err().contains("stats: mesh quad.obj: parsed in "), first.err());
        assertTrue(first.err().contains("written to the mesh cache in"), first.err());
        RenderCommandTest.Result second = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("2.pfm").toString(),
                                                                "--stats", "--cache-dir", cache);
        assertEquals(0, second.code(), second.err());
        assertTrue(second.err().matches("(?s).*stats: mesh quad\\.obj: read from the mesh cache in \\d+\\.\\d{3} s .*"), second.err());
        assertFalse(second.err().contains("parse quad.obj"), second.err());
        assertArrayEquals(Files.readAllBytes(dir.resolve("1.pfm")), Files.readAllBytes(dir.resolve("2.pfm")));
    }

    @Test
    void noCacheWritesNothingAndExcludesACacheFolder() throws IOException {
        Path scene = scene();
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("n.pfm").toString(), "--stats",
                                                           "--no-cache");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("stats: mesh quad.obj: parsed in ") && !r.err().contains("mesh cache"), r.err());
        RenderCommandTest.Result both = RenderCommandTest.run(scene.toString(), "-o", dir.resolve("n.pfm").toString(),
                                                              "--no-cache", "--cache-dir", dir.toString());
        assertEquals(ErrorReport.BAD_USAGE, both.code());
        assertEquals("render: error: --no-cache and --cache-dir exclude each other (see render --help)", both.err().strip());
    }

    /** A grid OBJ of about 420 KB in {@code folder}, under {@code name}: large enough to be cached. */
    private static Path grid(Path folder, String name) throws IOException {
        Files.createDirectories(folder);
        StringBuilder obj = new StringBuilder();
        int n = 90;
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                obj.append("v ").append((double) i / n - 0.5).append(" 0 ").append((double) j / n - 0.5).append('\n');
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1;
                obj.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + n + 2).append(' ').append(a + n + 1).append('\n');
            }
        }
        Path file = Files.writeString(folder.resolve(name), obj);
        Files.writeString(folder.resolve("s.yaml"), "image: {width: 8, height: 6, samples: 1}\n"
            + "camera: {eye: [0, 2, 3], look-at: [0, 0, 0], fov: 50}\n"
            + "lights:\n  - {type: point, position: [0, 2, 1], intensity: 5}\n"
            + "objects:\n  - {type: mesh, file: \"" + name + "\"}\n");
        return file;
    }

    private RenderCommandTest.Result render(Path folder, String cache, String... more) {
        String[] args = java.util.stream.Stream.concat(java.util.stream.Stream.of(folder.resolve("s.yaml").toString(), "-o",
            folder.resolve("o.pfm").toString(), "--stats", "--cache-dir", cache), java.util.stream.Stream.of(more))
            .toArray(String[]::new);
        return RenderCommandTest.run(args);
    }

    private static long entries(Path cache) throws IOException {
        try (var files = Files.list(cache)) {
            return files.filter(p -> p.toString().endsWith(".mesh")).count();
        }
    }

    /** The same file in three folders is one entry, read by the second and third. */
    @Test
    void copiesOfOneFileShareOneEntry() throws IOException {
        String cache = dir.resolve("meshes").toString();
        for (String folder : new String[] {"a", "b", "c"}) {
            grid(dir.resolve(folder), "g.obj");
            RenderCommandTest.Result r = render(dir.resolve(folder), cache);
            assertEquals(0, r.code(), r.err());
            assertEquals(!folder.equals("a"), r.err().contains("read from the mesh cache"), folder + ": " + r.err());
        }
        assertEquals(1, entries(Path.of(cache)));
    }

    /** A tiny mesh is not cached; a name of 240 characters is, under a short name, without a warning. */
    @Test
    void tinyMeshesAreNotCachedAndLongNamesAre() throws IOException {
        Path cache = dir.resolve("meshes");
        Files.writeString(dir.resolve("t.yaml"), "objects:\n  - {type: mesh, file: t.obj}\nimage: {width: 4, height: 4, samples: 1}\n");
        Files.writeString(dir.resolve("t.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        RenderCommandTest.Result tiny = RenderCommandTest.run(dir.resolve("t.yaml").toString(), "-o", dir.resolve("t.png").toString(), "--stats",
                                     "--cache-dir", cache.toString());
        assertEquals(0, tiny.code(), tiny.err());
        assertTrue(tiny.err().contains("not cached (smaller than"), tiny.err());
        assertFalse(Files.exists(cache));
        grid(dir.resolve("long"), "x".repeat(240) + ".obj");
        RenderCommandTest.Result r = render(dir.resolve("long"), cache.toString());
        assertEquals(0, r.code(), r.err());
        assertFalse(r.err().contains("warning"), r.err());
        assertEquals(1, entries(cache));
        assertTrue(render(dir.resolve("long"), cache.toString()).err().contains("read from the mesh cache"));
    }

    /** A killed writer's temporary file, an hour old, is removed; the cap evicts; both are options. */
    @Test
    void stalePartialsGoAndTheCapHolds() throws IOException {
        Path cache = Files.createDirectories(dir.resolve("meshes"));
        // what a killed writer leaves: the entry's temporary name, the format's magic bytes and part of the rest
        Path stale = Files.writeString(cache.resolve(".g.obj-0123456789abcdef.mesh.k1.partial"), "RTMESH\0\0killed");
        Files.setLastModifiedTime(stale, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis() - 7_200_000));
        grid(dir.resolve("a"), "g.obj");
        assertEquals(0, render(dir.resolve("a"), cache.toString()).code());
        assertFalse(Files.exists(stale));
        grid(dir.resolve("b"), "h.obj");
        // room for one entry of the grid (SAH tree: 674 KB; the median tree's, 524 KB) but not two
        RenderCommandTest.Result capped = render(dir.resolve("b"), cache.toString(), "--cache-max", "1M");
        assertEquals(0, capped.code(), capped.err());
        assertTrue(capped.err().contains("1 least recently used entry evicted"), capped.err());
        assertEquals(1, entries(cache));
        RenderCommandTest.Result bad = render(dir.resolve("b"), cache.toString(), "--cache-max", "lots");
        assertEquals(ErrorReport.BAD_USAGE, bad.code());
        assertTrue(bad.err().contains("--cache-max: a size such as 512M or 2G is expected, got 'lots'"), bad.err());
        assertEquals(3L << 30, RenderOptions.cacheMax(null, java.util.Map.of("RAYTRACER_MESH_CACHE_MAX", "3G")));
        assertEquals(1L << 20, RenderOptions.cacheMax("1M", java.util.Map.of("RAYTRACER_MESH_CACHE_MAX", "3G")), "the option wins");
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(
            IllegalArgumentException.class, () -> RenderOptions.cacheMax(null, java.util.Map.of("RAYTRACER_MESH_CACHE_MAX", "x")));
        assertTrue(e.getMessage().startsWith("RAYTRACER_MESH_CACHE_MAX: "), e.getMessage());
    }
}

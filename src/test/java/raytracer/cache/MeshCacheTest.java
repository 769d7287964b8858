package raytracer.cache;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.accel.BvhFile;
import raytracer.accel.MeshBVH;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.LoadReport;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;
import raytracer.math.BBox;
import raytracer.render.SceneAnalysis;
import raytracer.render.Renders;
import raytracer.shapes.mesh.Mesh;

/**
 * The mesh cache gives back exactly what was parsed and built (arrays, tree, image), and never
 * trusts an entry that is truncated, damaged, of another version (replaced without a warning), or older than its OBJ or MTL
 * file: each is a warning, the mesh is parsed and built again, and the entry rewritten.
 */
class MeshCacheTest {
    @TempDir
    Path dir;

    /** A wavy grid of quads with texture coordinates, normals and two MTL materials. */
    private Path grid(int n) throws IOException {
        Files.writeString(dir.resolve("grid.mtl"), "newmtl a\nKd 0.8 0.3 0.2\nnewmtl b\nKd 0.2 0.5 0.8\nKs 0.4 0.4 0.4\nNs 30\n");
        StringBuilder obj = new StringBuilder("mtllib grid.mtl\n");
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                double x = (double) i / n - 0.5;
                double z = (double) j / n - 0.5;
                obj.append("v ").append(x).append(' ').append(0.1 * Math.sin(7 * x + 3 * z)).append(' ').append(z).append('\n');
                obj.append("vt ").append((double) i / n).append(' ').append((double) j / n).append('\n');
                obj.append("vn 0 1 ").append(0.1 * x).append('\n');
            }
        }
        for (int j = 0; j < n; j++) {
            obj.append(j % 2 == 0 ? "usemtl a\n" : "usemtl b\n");
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1;
                int b = a + 1;
                int c = a + n + 2;
                int d = a + n + 1;
                obj.append("f ").append(corner(a)).append(corner(b)).append(corner(c)).append(corner(d)).append('\n');
            }
        }
        return Files.writeString(dir.resolve("grid.obj"), obj);
    }

    private static String corner(int v) {
        return v + "/" + v + "/" + v + " ";
    }

    private Path scene(String options) throws IOException {
        return Files.writeString(dir.resolve("s.yaml"), "image: {width: 24, height: 18, samples: 1}\n"
            + "camera: {eye: [0, 1.2, 1.2], look-at: [0, 0, 0], fov: 50}\n"
            + "lights:\n  - {type: point, position: [0.5, 2, 1], intensity: 5}\n"
            + "objects:\n  - {type: mesh, file: grid.obj" + options + "}\n");
    }

    private MeshCache cache() {
        // every mesh cached, however small
        return MeshCache.in(dir.resolve("cache"), Long.MAX_VALUE, 0);
    }

    /** A load, prepared, with its mesh object, its report and its image (PFM bytes). */
    private record Run(MeshBVH mesh, LoadReport report, byte[] image) {
    }

    private Run run(Path scene, MeshCache cache) throws IOException, SceneException {
        return run(scene, cache, () -> { });
    }

    /** As {@link #run(Path, MeshCache)}, with the scene analysis on, and {@code between} run after loading, before preparing. */
    private Run run(Path scene, MeshCache cache, IoStep between) throws IOException, SceneException {
        LoadedScene loaded = SceneLoader.load(scene, cache);
        World world = loaded.world();
        SceneAnalysis.apply(world, loaded.rayTree());
        between.run();
        world.prepare();
        Film film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
        Renders.render(world, 1, 1, film);
        Path pfm = dir.resolve("image.pfm");
        ImageWriters.write(film, 1, pfm);
        MeshBVH mesh = world.objects().isEmpty() ? null : (MeshBVH) world.objects().get(0);
        return new Run(mesh, loaded.report(), Files.readAllBytes(pfm));
    }

    @FunctionalInterface
    private interface IoStep {
        void run() throws IOException;
    }

    private Path entry() throws IOException {
        try (Stream<Path> files = cacheFiles(dir.resolve("cache"))) {
            List<Path> all = files.toList();
            assertEquals(1, all.size(), all.toString());
            return all.get(0);
        }
    }

    private static byte[] bytes(MeshBVH mesh) {
        ByteBuffer buffer = ByteBuffer.allocate((int) BvhFile.size(mesh.bvh())).order(ByteOrder.LITTLE_ENDIAN);
        BvhFile.write(mesh.bvh(), buffer);
        return buffer.array();
    }

    private static boolean mentions(LoadReport report, String text) {
        return report.statistics().stream().anyMatch(s -> s.contains(text));
    }

    @Test
    void whatIsReadBackIsWhatWasBuilt() throws IOException, SceneException {
        Path scene = scene("");
        grid(12);
        Run parsed = run(scene, null);
        Run first = run(scene, cache());
        Run second = run(scene, cache());
        assertTrue(mentions(first.report(), "written to the mesh cache"), first.report().statistics().toString());
        assertTrue(mentions(second.report(), "read from the mesh cache in"), second.report().statistics().toString());
        assertFalse(second.report().timings().keySet().stream().anyMatch(k -> k.startsWith("parse")), "not parsed");
        Mesh a = parsed.mesh().mesh();
        Mesh b = second.mesh().mesh();
        assertArrayEquals(a.positions(), b.positions());
        assertArrayEquals(a.normals(), b.normals());
        assertArrayEquals(a.uvs(), b.uvs());
        assertArrayEquals(a.triangles(), b.triangles());
        assertArrayEquals(a.materialIds(), b.materialIds());
        assertArrayEquals(bytes(parsed.mesh()), bytes(second.mesh()), "the same tree");
        assertEquals(parsed.mesh().materials().size(), second.mesh().materials().size(), "the MTL materials");
        assertArrayEquals(parsed.image(), second.image());
        assertEquals(List.of(), second.report().warnings());
    }

    @Test
    void aDamagedOrStaleEntryIsRebuiltWithAWarning() throws IOException, SceneException {
        Path scene = scene(", smooth: true");
        Path obj = grid(8);
        Run reference = run(scene, cache());
        Path entry = entry();
        byte[] good = Files.readAllBytes(entry);
        // truncated: seen from the header's length at load
        try (RandomAccessFile f = new RandomAccessFile(entry.toFile(), "rw")) {
            f.setLength(good.length - 100);
        }
        expectRebuilt(scene, reference, "is unusable (it is truncated");
        assertArrayEquals(good, Files.readAllBytes(entry), "rewritten as it was");
        // one byte of the positions flipped: only the checksum sees it, when the arrays are read
        byte[] flipped = good.clone();
        flipped[good.length / 3] ^= 0x10;
        Files.write(entry, flipped);
        expectRebuilt(scene, reference, "its checksum does not match");
        assertArrayEquals(good, Files.readAllBytes(entry));
        // written by another version of the format, as every entry is after an upgrade: replaced without a warning
        byte[] other = good.clone();
        other[8]++;
        Files.write(entry, other);
        Run upgraded = run(scene, cache());
        assertEquals(List.of(), upgraded.report().warnings());
        assertTrue(mentions(upgraded.report(), "written to the mesh cache"), upgraded.report().statistics().toString());
        assertArrayEquals(reference.image(), upgraded.image());
        assertArrayEquals(good, Files.readAllBytes(entry));
        // the OBJ changed (a comment added: the same mesh, another file): entries are keyed by content,
        // so this is another entry, written beside the old one (which the cap will evict when it is the least used)
        Files.writeString(obj, Files.readString(obj) + "# edited\n");
        Run edited = run(scene, cache());
        assertEquals(List.of(), edited.report().warnings());
        assertTrue(mentions(edited.report(), "written to the mesh cache"), edited.report().statistics().toString());
        assertArrayEquals(reference.image(), edited.image());
        try (Stream<Path> files = cacheFiles(dir.resolve("cache"))) {
            assertEquals(2, files.count());
        }
        // an MTL file it read changed
        Files.writeString(dir.resolve("grid.mtl"), Files.readString(dir.resolve("grid.mtl")) + "# edited\n");
        expectRebuilt(scene, reference, "grid.mtl changed since");
        Run again = run(scene, cache());
        assertEquals(List.of(), again.report().warnings(), "the rewritten entry is used");
        assertTrue(mentions(again.report(), "read from the mesh cache"));
    }

    private void expectRebuilt(Path scene, Run reference, String warning) throws IOException, SceneException {
        Run rebuilt = run(scene, cache());
        assertEquals(1, rebuilt.report().warnings().size(), rebuilt.report().warnings().toString());
        assertTrue(rebuilt.report().warnings().get(0).contains(warning), rebuilt.report().warnings().toString());
        assertTrue(mentions(rebuilt.report(), "written to the mesh cache"), rebuilt.report().statistics().toString());
        assertArrayEquals(reference.image(), rebuilt.image());
    }

    /** Where the big-endian bytes of {@code value} first occur in {@code bytes} (the header is written by DataOutput). */
    private static int find(byte[] bytes, double value) {
        byte[] pattern = ByteBuffer.allocate(8).putDouble(value).array();
        outer:
        for (int i = 0; i + 8 <= bytes.length; i++) {
            for (int k = 0; k < 8; k++) {
                if (bytes[i + k] != pattern[k]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("value " + value + " not found");
    }

    /**
     * The header is checked with everything else before any of it is used. Before, bounds moved
     * out of view made the scene analysis leave the mesh out, so the entry was never read and never
     * failed its checksum: the mesh was missing from every image without a word; a
     * damaged Kd warned "parsed again" but rendered with the header's colour.
     */
    @Test
    void aDamagedHeaderIsNeverUsed() throws IOException, SceneException {
        Path scene = scene("");
        grid(8);
        Run reference = run(scene, cache());
        Path entry = entry();
        byte[] good = Files.readAllBytes(entry);
        BBox box = reference.mesh().mesh().bounds();
        // the bounds moved 1000 units to the side: out of the camera's view
        byte[] moved = good.clone();
        ByteBuffer.wrap(moved).putDouble(find(good, box.x0()), box.x0() + 1000).putDouble(find(good, box.x1()), box.x1() + 1000);
        Files.write(entry, moved);
        expectRebuilt(scene, reference, "its checksum does not match");
        // material a's Kd 0.8 0.3 0.2 made green
        byte[] recoloured = good.clone();
        ByteBuffer.wrap(recoloured).putDouble(find(good, 0.8), 0).putDouble(find(good, 0.3), 1);
        Files.write(entry, recoloured);
        expectRebuilt(scene, reference, "its checksum does not match");
    }

    /**
     * An entry is read once. Before, its header was read when the scene was loaded
     * and its arrays when it was prepared, through two opens: an entry replaced in between rendered
     * one version's geometry with the other's materials and bounds, silently.
     */
    @Test
    void anEntryReplacedAfterLoadingIsNotMixedIn() throws IOException, SceneException {
        Path scene = scene("");
        // another valid entry: the grid of 4 written by the same program, in another folder
        String grid4 = Files.readString(grid(4));
        Path other = Files.createDirectories(dir.resolve("other"));
        Files.copy(dir.resolve("grid.mtl"), other.resolve("grid.mtl"));
        Files.writeString(other.resolve("grid.obj"), grid4);
        Files.copy(scene, other.resolve("s.yaml"));
        run(other.resolve("s.yaml"), MeshCache.in(other.resolve("cache"), Long.MAX_VALUE, 0));
        byte[] otherEntry;
        try (Stream<Path> files = cacheFiles(other.resolve("cache"))) {
            otherEntry = Files.readAllBytes(files.findFirst().orElseThrow());
        }
        grid(8);
        Run reference = run(scene, cache());
        Path entry = entry();
        Run mixed = run(scene, cache(), () -> Files.write(entry, otherEntry));
        assertTrue(mentions(mixed.report(), "read from the mesh cache"), mixed.report().statistics().toString());
        assertArrayEquals(reference.image(), mixed.image(), "the entry as it was when the scene was loaded");
        assertEquals(List.of(), mixed.report().warnings());
    }

    /**
     * A rewritten entry gets the umask's permissions, not those of what it
     * replaces. Before, a mode-000 entry was rebuilt every run with mode 000 again (for anyone but
     * root: a warning each time, never healing), and an entry that was a link to a world-writable
     * file was rewritten world-writable.
     */
    @Test
    void aRewrittenEntryHasTheUmasksPermissions() throws IOException, SceneException {
        Path scene = scene("");
        grid(6);
        Run reference = run(scene, cache());
        Path entry = entry();
        Path fresh = dir.resolve("fresh");
        Files.newOutputStream(fresh).close();
        Set<PosixFilePermission> umask = Files.getPosixFilePermissions(fresh);
        byte[] damaged = Files.readAllBytes(entry);
        damaged[damaged.length / 2] ^= 1;
        Files.write(entry, damaged);
        Files.setPosixFilePermissions(entry, Set.of());
        // root reads it anyway and finds the damage; anyone else cannot read it: either way it is rewritten
        Run rebuilt = run(scene, cache());
        assertArrayEquals(reference.image(), rebuilt.image());
        assertEquals(umask, Files.getPosixFilePermissions(entry), "the umask's permissions, not 000");
        // an entry that is a link to a world-writable file this test made
        Path open = dir.resolve("open");
        Files.write(open, damaged);
        Files.setPosixFilePermissions(open, PosixFilePermissions.fromString("rw-rw-rw-"));
        Files.delete(entry);
        Files.createSymbolicLink(entry, open);
        run(scene, cache());
        assertFalse(Files.isSymbolicLink(entry), "the link is replaced by an entry of this program's own");
        assertEquals(umask, Files.getPosixFilePermissions(entry));
        assertArrayEquals(damaged, Files.readAllBytes(open), "the link's target is untouched");
    }

    @Test
    void eachSetOfOptionsHasItsEntry() throws IOException, SceneException {
        grid(4);
        Run first = run(scene(""), cache());
        assertTrue(mentions(first.report(), "sah BVH built"), first.report().statistics().toString());
        run(scene(", smooth: true"), cache());
        run(scene(", bvh: median"), cache());
        try (Stream<Path> files = cacheFiles(dir.resolve("cache"))) {
            assertEquals(3, files.count());
        }
        assertTrue(mentions(run(scene(", bvh: median"), cache()).report(), "read from the mesh cache"));
        // an entry names its builder even when the scene left it to the default: a scene naming
        // the default reads that entry, and a change of default would read no other builder's tree
        assertTrue(mentions(run(scene(", bvh: sah"), cache()).report(), "read from the mesh cache"));
    }

    @Test
    void aParseThatWarnsIsNotCached() throws IOException, SceneException {
        Files.writeString(dir.resolve("grid.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nfrobnicate 3\nf 1 2 3\n");
        Run r = run(scene(""), cache());
        assertEquals(1, r.report().warnings().size(), r.report().warnings().toString());
        assertTrue(mentions(r.report(), "not cached (its parse warned)"), r.report().statistics().toString());
        assertFalse(Files.exists(dir.resolve("cache")));
    }

    @Test
    void aCacheThatCannotBeWrittenIsAWarning() throws IOException, SceneException {
        grid(4);
        Files.writeString(dir.resolve("cache"), "a file where the folder should be");
        Run r = run(scene(""), cache());
        assertEquals(1, r.report().warnings().size(), r.report().warnings().toString());
        assertTrue(r.report().warnings().get(0).startsWith("cannot write the mesh cache"), r.report().warnings().toString());
        assertArrayEquals(run(scene(""), null).image(), r.image());
    }

    @Test
    void theDefaultFolderFollowsXdg() {
        assertEquals(Path.of("/x/raytracer/meshes"), MeshCache.defaultDir(Map.of("XDG_CACHE_HOME", "/x"), "/home/u"));
        assertEquals(Path.of("/home/u/.cache/raytracer/meshes"), MeshCache.defaultDir(Map.of(), "/home/u"));
        assertEquals(Path.of("/home/u/.cache/raytracer/meshes"), MeshCache.defaultDir(Map.of("XDG_CACHE_HOME", "rel"), "/home/u"));
    }

    /** The files of a cache folder but its lock file, which stays once made. */
    private static Stream<Path> cacheFiles(Path folder) throws IOException {
        return Files.list(folder).filter(p -> !p.getFileName().toString().equals(".raytracer-cache.lock"));
    }
}

package raytracer.io.scene;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import raytracer.accel.FlatBVH;
import raytracer.image.FileKind;
import raytracer.image.IoReason;
import raytracer.io.obj.ObjModel;
import raytracer.shapes.mesh.Mesh;

/**
 * Where parsed meshes and their BVHs are kept between runs ({@link MeshCacheFile}), so that a mesh
 * rendered again is read back in bulk instead of parsed and built. One file per OBJ file and set
 * of options ({@code <name>-<hash of path and options>.mesh}), so a changed file replaces its
 * entry rather than adding one.
 *
 * <p>An entry is used only when the OBJ file and every MTL file it read have the size,
 * modification time and CRC-32C of their bytes that they had when it was written (the checksum of
 * the whole file: 8 MB take about 2 ms with the CPU's CRC instruction, against 20-30 ms for
 * SHA-256; 32 bits are plenty to tell an edited file from the same one, with size and time
 * besides, though not to resist a forgery), was made with the same options (smoothing, builder,
 * leaf size) and by the same versions of the formats, and passes its own checksum. Anything else
 * is a warning, and the mesh is parsed and built again, and the entry rewritten. A parse that warned
 * about something (a missing texture, say) is not cached, so the warning and its cause are found
 * afresh each time.
 */
public final class MeshCache {
    private final Path dir;

    private MeshCache(Path dir) {
        this.dir = dir;
    }

    /** A cache in {@code dir}, created when the first entry is written. */
    public static MeshCache in(Path dir) {
        return new MeshCache(dir);
    }

    /** $XDG_CACHE_HOME/raytracer/meshes, or ~/.cache/raytracer/meshes. */
    public static Path defaultDir(Map<String, String> environment, String home) {
        String xdg = environment.get("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute() ? Path.of(xdg) : Path.of(home, ".cache");
        return base.resolve("raytracer").resolve("meshes");
    }

    public Path dir() {
        return dir;
    }

    /** Makes the folder, saying so when something else is at its name. */
    private void createDir() throws IOException {
        FileKind kind = FileKind.of(dir);
        if (kind != FileKind.DIRECTORY && kind != FileKind.MISSING) {
            throw new IOException(dir + " is " + kind.words() + ", not a folder");
        }
        Files.createDirectories(dir);
    }

    /**
     * Looks for the entry of {@code obj} made with {@code options}, reading it whole: nothing of an
     * entry is used before all of it is checked. A stale or damaged entry is a warning and counts as none; an OBJ file that cannot be read counts as none, silently (its
     * parse will say why).
     */
    Lookup lookup(Path obj, String options, Consumer<String> warn) {
        MeshCacheFile.Stamp stamp;
        try {
            stamp = MeshCacheFile.stamp(obj);
        } catch (IOException e) {
            return new Lookup(this, null, options, null, null);
        }
        Path file = dir.resolve(obj.getFileName() + "-" + key(stamp.path(), options) + ".mesh");
        if (!Files.isRegularFile(file)) {
            return new Lookup(this, file, options, stamp, null);
        }
        try {
            MeshCacheFile.Contents contents = MeshCacheFile.read(file);
            String stale = stale(contents.header(), stamp, options);
            if (stale == null) {
                return new Lookup(this, file, options, stamp, contents);
            }
            warn.accept("mesh cache " + file + " is stale (" + stale + "); " + obj.getFileName() + " is parsed again");
        } catch (IOException e) {
            warn.accept("mesh cache " + file + " is unusable (" + IoReason.of(e) + "); " + obj.getFileName()
                        + " is parsed again");
        }
        return new Lookup(this, file, options, stamp, null);
    }

    /** Why an entry no longer matches its sources, or null when it does. */
    private static String stale(MeshCacheFile.Header header, MeshCacheFile.Stamp source, String options) {
        if (!header.source().equals(source)) {
            return header.source().path().equals(source.path()) ? "the OBJ file changed since" : "it is of another file";
        }
        if (!header.options().equals(options)) {
            return "made with " + header.options();
        }
        for (MeshCacheFile.Stamp library : header.libraries()) {
            try {
                if (!MeshCacheFile.stamp(Path.of(library.path())).equals(library)) {
                    return library.path() + " changed since";
                }
            } catch (IOException e) {
                return library.path() + " cannot be read";
            }
        }
        return null;
    }

    /** The first 16 hex digits of SHA-256 over the file's path and the options. */
    private static String key(String path, String options) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            byte[] digest = sha.digest((path + "\n" + options).getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(digest).substring(0, 16);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }

    /**
     * One OBJ file's place in the cache: the entry found, read whole and checked ({@link #contents},
     * null when none is usable), or where to write one after building.
     */
    static final class Lookup {
        private final MeshCache cache;
        private final Path file;
        private final String options;
        private final MeshCacheFile.Stamp source;
        private MeshCacheFile.Contents contents;

        private Lookup(MeshCache cache, Path file, String options, MeshCacheFile.Stamp source, MeshCacheFile.Contents contents) {
            this.cache = cache;
            this.file = file;
            this.options = options;
            this.source = source;
            this.contents = contents;
        }

        /** The usable entry's header, or null. */
        MeshCacheFile.Header header() {
            return contents == null ? null : contents.header();
        }

        Path file() {
            return file;
        }

        /** The usable entry's mesh and tree, as read and checked when it was looked up; the lookup lets go of them. */
        MeshCacheFile.Contents take() {
            MeshCacheFile.Contents taken = contents;
            contents = null;
            return taken;
        }

        /**
         * Writes the entry for {@code model} as built into {@code mesh}; a model that warned, or a
         * folder that cannot be written, is not cached (the second with a warning). True if written.
         */
        boolean store(ObjModel model, Mesh mesh, FlatBVH bvh, Consumer<String> warn) {
            if (source == null || !model.warnings().isEmpty()) {
                return false;
            }
            try {
                List<MeshCacheFile.Stamp> libraries = new ArrayList<>();
                for (Path library : model.libraries()) {
                    libraries.add(MeshCacheFile.stamp(library));
                }
                MeshCacheFile.Header h = new MeshCacheFile.Header(source, options, libraries, model.faces(), model.ngons(),
                    model.mesh().vertexCount(), model.mesh().triangleCount(), model.mesh().hasNormals(),
                    model.mesh().hasUvs(), model.mesh().materialIds() != null, model.mesh().bounds(), model.materials(),
                    model.sheets());
                cache.createDir();
                MeshCacheFile.write(file, h, mesh, bvh);
                return true;
            } catch (IOException e) {
                warn.accept("cannot write the mesh cache " + file + " (" + IoReason.of(e) + "); the mesh will be parsed again next time");
                return false;
            } catch (RuntimeException e) {
                warn.accept("cannot write the mesh cache " + file + " (" + (e.getMessage() != null ? e.getMessage()
                            : e.getClass().getSimpleName()) + "); the mesh will be parsed again next time");
                return false;
            }
        }
    }
}

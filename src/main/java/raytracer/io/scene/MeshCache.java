package raytracer.io.scene;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import raytracer.accel.FlatBVH;
import raytracer.cache.CacheFolder;
import raytracer.cache.ContentStamp;
import raytracer.image.IoReason;
import raytracer.io.obj.ObjModel;
import raytracer.shapes.mesh.Mesh;

/**
 * Where parsed meshes and their BVHs are kept between runs ({@link MeshCacheFile}), so that a mesh
 * rendered again is read back in bulk instead of parsed and built.
 *
 * <p><b>Keys.</b> An entry is named by the OBJ file's content and the options
 * ({@code <name>-<16 hex digits>.mesh}, the name cut to {@value #NAME_CHARS} characters): copies of
 * one file in several folders share one entry, and an edited file gets another. The content is
 * identified by its size and two 32-bit checksums of all its bytes, CRC-32C and CRC-32 (64 bits:
 * the odds that two different files of one size pass as one are 2^-64; both run at several GB/s
 * with the CPU's instructions, where SHA-256 took over 200 ms for 8 MB in a cold JVM; not meant to
 * resist a forgery). An entry is used only when the MTL files it read, found from the OBJ file's
 * folder by the same relative paths, have the contents they had, it was made with the same options
 * (smoothing, builder, leaf size) by the same versions of the formats, and it passes every check of
 * {@link MeshCacheFile#read}. Anything else is a warning, and the mesh is parsed and built again,
 * and the entry rewritten. A parse that warned about something (a missing texture, say) is not
 * cached, so the warning and its cause are found afresh each time.
 *
 * <p><b>Limits.</b> A mesh file smaller than {@link #MIN_OBJ_BYTES} (uncompressed) is neither
 * looked up nor written: parsing it takes about as long as reading its entry (docs/performance.md).
 * The entries together stay under a cap ({@link #DEFAULT_MAX_BYTES}, {@code --cache-max} or
 * {@value #MAX_ENV}): after writing an entry, the least recently used others are deleted until
 * they fit (an entry read is marked used by its modification time). Temporary files that a killed
 * writer left behind are deleted once they are {@link CacheFolder#STALE_PARTIAL} old. The folder may
 * hold the user's own files too: {@link CacheFolder} deletes only entries it can prove are the
 * cache's ({@link #ENTRY_NAME} and the file format's magic bytes).
 */
public final class MeshCache {
    /** The default cap: some 30 entries of the 871k-triangle dragon (31 MiB each), a small part of a laptop's disk. */
    public static final long DEFAULT_MAX_BYTES = 1L << 30;
    /** The environment variable that sets the cap when --cache-max does not. */
    public static final String MAX_ENV = "RAYTRACER_MESH_CACHE_MAX";
    /**
     * OBJ files smaller than this (uncompressed) are not cached: measured in a cold JVM, parsing and
     * building took 24-60 ms up to 127 KiB (4k triangles), against 50-70 ms to look up and read an
     * entry; from 230 KiB (7k triangles) on the cache was faster (docs/performance.md).
     */
    public static final long MIN_OBJ_BYTES = 192 << 10;
    /** The most characters of the OBJ file's name kept in an entry's name. */
    static final int NAME_CHARS = 48;
    /** An entry's name, as {@link #entryName} makes it. */
    static final String ENTRY_NAME = "[A-Za-z0-9._-]{1," + NAME_CHARS + "}-[0-9a-f]{16}\\.mesh";

    private final Path dir;
    private final CacheFolder folder;
    private final long maxBytes;
    private final long minObjBytes;

    private MeshCache(Path dir, long maxBytes, long minObjBytes) {
        this.dir = dir;
        this.folder = new CacheFolder(dir, ENTRY_NAME, MeshCacheFile.MAGIC_BYTES);
        this.maxBytes = maxBytes;
        this.minObjBytes = minObjBytes;
    }

    /** A cache in {@code dir} with the default cap, created when the first entry is written. */
    public static MeshCache in(Path dir) {
        return in(dir, DEFAULT_MAX_BYTES);
    }

    /** A cache in {@code dir} whose entries stay under {@code maxBytes} together. */
    public static MeshCache in(Path dir, long maxBytes) {
        return in(dir, maxBytes, MIN_OBJ_BYTES);
    }

    /** As {@link #in(Path, long)}, caching OBJ files from {@code minObjBytes} on (tests cache tiny meshes). */
    static MeshCache in(Path dir, long maxBytes, long minObjBytes) {
        return new MeshCache(dir, maxBytes, minObjBytes);
    }

    /** $XDG_CACHE_HOME/raytracer/meshes, or ~/.cache/raytracer/meshes. */
    public static Path defaultDir(Map<String, String> environment, String home) {
        String xdg = environment.get("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute() ? Path.of(xdg) : Path.of(home, ".cache");
        return base.resolve("raytracer").resolve("meshes");
    }

    /**
     * A size in bytes as a person writes it: {@code 2G}, {@code 512M}, {@code 100K} (powers of
     * 1024), or a plain number of bytes; IllegalArgumentException otherwise.
     */
    public static long parseSize(String text) {
        String t = text.strip().toUpperCase(Locale.ROOT);
        if (t.endsWith("B") && t.length() > 1 && !Character.isDigit(t.charAt(t.length() - 2))) {
            t = t.substring(0, t.length() - 1); // 2GB, 512MB
        }
        int shift = t.isEmpty() ? 0 : switch (t.charAt(t.length() - 1)) {
            case 'K' -> 10;
            case 'M' -> 20;
            case 'G' -> 30;
            case 'T' -> 40;
            default -> 0;
        };
        String digits = shift == 0 ? t : t.substring(0, t.length() - 1);
        try {
            long n = Long.parseLong(digits);
            if (n < 0 || n > Long.MAX_VALUE >> shift) {
                throw new NumberFormatException();
            }
            return n << shift;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("a size such as 512M or 2G is expected, got '" + text + "'");
        }
    }

    public Path dir() {
        return dir;
    }

    /**
     * Looks for the entry of {@code obj} made with {@code options}, reading it whole: nothing of an
     * entry is used before all of it is checked, and an entry used is marked as used now. A stale
     * or damaged entry is a warning and counts as none; an OBJ file that cannot be read counts as
     * none, silently (its parse will say why); a small one is not looked up.
     */
    Lookup lookup(Path obj, String options, Consumer<String> warn) {
        ContentStamp stamp;
        try {
            if (uncompressedSize(obj) < minObjBytes) {
                return new Lookup(this, obj, null, options, null, null, String.format(Locale.ROOT,
                    "smaller than %d KiB: parsed about as fast as read", minObjBytes / 1024));
            }
            stamp = ContentStamp.of(obj, "");
        } catch (IOException e) {
            return new Lookup(this, obj, null, options, null, null, null);
        }
        Path file = dir.resolve(entryName(obj, stamp, options));
        if (!Files.isRegularFile(file)) {
            return new Lookup(this, obj, file, options, stamp, null, null);
        }
        Path folder = obj.toAbsolutePath().getParent();
        try {
            MeshCacheFile.Contents contents = MeshCacheFile.read(file, folder);
            String stale = stale(contents.header(), stamp, options, folder);
            if (stale == null) {
                CacheFolder.markUsed(file);
                return new Lookup(this, obj, file, options, stamp, contents, null);
            }
            warn.accept("mesh cache " + file + " is stale (" + stale + "); " + obj.getFileName() + " is parsed again");
        } catch (MeshCacheFile.OtherVersion e) {
            // left by an older or newer program: rewritten below, as an entry never written would be
        } catch (IOException e) {
            warn.accept("mesh cache " + file + " is unusable (" + IoReason.of(e) + "); " + obj.getFileName()
                        + " is parsed again");
        }
        return new Lookup(this, obj, file, options, stamp, null, null);
    }

    /** The bytes of the OBJ text: the file's size, or for gzip the larger of it and the trailer's ISIZE (the size mod 2^32). */
    private static long uncompressedSize(Path obj) throws IOException {
        long size = Files.size(obj);
        if (!obj.getFileName().toString().endsWith(".gz") || size < 18) {
            return size;
        }
        try (FileChannel channel = FileChannel.open(obj, StandardOpenOption.READ)) {
            ByteBuffer trailer = ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN);
            channel.read(trailer, size - 4);
            return Math.max(size, Integer.toUnsignedLong(trailer.getInt(0)));
        }
    }

    /** Why an entry no longer matches its sources, or null when it does. */
    private static String stale(MeshCacheFile.Header header, ContentStamp source, String options, Path folder) {
        if (!header.source().equals(source)) {
            return "it is of another file";
        }
        if (!header.options().equals(options)) {
            return "made with " + header.options();
        }
        for (ContentStamp library : header.libraries()) {
            Path file = folder.resolve(library.path()).normalize();
            try {
                if (!ContentStamp.of(file, library.path()).equals(library)) {
                    return file + " changed since";
                }
            } catch (IOException e) {
                return file + " cannot be read";
            }
        }
        return null;
    }

    /**
     * {@code <name>-<key>.mesh}: the OBJ file's name, cut and with only plain characters kept (a
     * long name would not fit a folder entry with the temporary file's additions), and the first
     * 16 hex digits of a SHA-256 over its content's identity and the options.
     */
    static String entryName(Path obj, ContentStamp content, String options) {
        String name = obj.getFileName().toString().replaceAll("[^A-Za-z0-9._-]", "_");
        if (name.length() > NAME_CHARS) {
            name = name.substring(0, NAME_CHARS);
        }
        String identity = content.identity() + "\n" + options;
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(identity.getBytes(StandardCharsets.UTF_8));
            return name + "-" + HexFormat.of().formatHex(digest).substring(0, 16) + ".mesh";
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }

    /** What storing an entry did: written, with how many others were evicted to stay under the cap; or why not. */
    record Stored(boolean written, int evicted, String whyNot) {
    }

    /**
     * One OBJ file's place in the cache: the entry found, read whole and checked ({@link #take},
     * null when none is usable), or where to write one after building, or why there is none.
     */
    static final class Lookup {
        private final MeshCache cache;
        private final Path obj;
        private final Path file;
        private final String options;
        private final ContentStamp source;
        private MeshCacheFile.Contents contents;
        /** Why the mesh is not cached at all (too small), or null. */
        private final String notCached;

        private Lookup(MeshCache cache, Path obj, Path file, String options, ContentStamp source,
                       MeshCacheFile.Contents contents, String notCached) {
            this.cache = cache;
            this.obj = obj;
            this.file = file;
            this.options = options;
            this.source = source;
            this.contents = contents;
            this.notCached = notCached;
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
         * Writes the entry for {@code model} (its figures; its mesh may be gone) as built into {@code mesh} and {@code bvh}, then keeps
         * the cache under its cap; a small mesh, a model that warned, an entry larger than the cap
         * or a folder that cannot be written is not cached (the last with a warning).
         */
        Stored store(ObjModel model, Mesh mesh, FlatBVH bvh, Consumer<String> warn) {
            if (notCached != null) {
                return new Stored(false, 0, notCached);
            }
            if (source == null) {
                return new Stored(false, 0, null);
            }
            if (!model.warnings().isEmpty()) {
                return new Stored(false, 0, "its parse warned");
            }
            long size = MeshCacheFile.size(mesh, bvh);
            if (size > cache.maxBytes) {
                return new Stored(false, 0, String.format(Locale.ROOT, "its entry of %.1f MiB is larger than the cache's cap "
                                                          + "of %.1f MiB", size / 1048576.0, cache.maxBytes / 1048576.0));
            }
            Path folder = obj.toAbsolutePath().getParent();
            try {
                List<ContentStamp> libraries = new ArrayList<>();
                for (Path library : model.libraries()) {
                    libraries.add(ContentStamp.of(library, folder.relativize(library.toAbsolutePath().normalize()).toString()));
                }
                MeshCacheFile.Header h = new MeshCacheFile.Header(source, options, libraries, model.faces(), model.ngons(),
                    mesh.vertexCount(), mesh.triangleCount(), mesh.hasNormals(), mesh.hasUvs(), mesh.materialIds() != null,
                    mesh.bounds(), model.materials(), model.sheets());
                CacheFolder.Trimmed trimmed = cache.folder.store(file, MeshCacheFile.body(h, mesh, bvh, folder), cache.maxBytes);
                if (trimmed.failure() != null) {
                    warn.accept("cannot keep the mesh cache " + cache.dir + " under its cap (" + IoReason.of(trimmed.failure()) + ")");
                }
                return new Stored(true, trimmed.evicted(), null);
            } catch (IOException e) {
                warn.accept("cannot write the mesh cache " + file + " (" + IoReason.of(e) + "); the mesh will be parsed again next time");
                return new Stored(false, 0, null);
            } catch (RuntimeException e) {
                warn.accept("cannot write the mesh cache " + file + " (" + (e.getMessage() != null ? e.getMessage()
                            : e.getClass().getSimpleName()) + "); the mesh will be parsed again next time");
                return new Stored(false, 0, null);
            }
        }
    }
}

package raytracer.cache;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import raytracer.image.IoReason;

/**
 * Where parsed meshes and their BVHs are kept between runs ({@link MeshCacheFile}), so that a mesh
 * rendered again is read back in bulk instead of parsed and built. The scene reader only looks a
 * mesh file up ({@link #lookup}) and, having built it, stores it ({@link MeshCacheLookup#store}).
 *
 * <p><b>Keys.</b> An entry is named by the OBJ file's content and the options
 * ({@code <name>-<16 hex digits>.mesh}, {@link EntryName}): copies of one file in several folders
 * share one entry, and an edited file gets another. The content is identified by its size and
 * {@link Checksum} ({@link ContentStamp}). An entry is used only when the MTL files it read, found
 * from the OBJ file's folder by the same relative paths, have the contents they had, it was made
 * with the same options (smoothing, builder, leaf size) by the same versions of the formats, and
 * it passes every check of {@link MeshCacheFile#read}. Anything else is a warning, and the mesh is parsed and built again,
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
    /** An entry's name, as {@link #entryName} makes it. */
    static final String ENTRY_NAME = EntryName.pattern("mesh");

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
    public static MeshCache in(Path dir, long maxBytes, long minObjBytes) {
        return new MeshCache(dir, maxBytes, minObjBytes);
    }

    /** $XDG_CACHE_HOME/raytracer/meshes, or ~/.cache/raytracer/meshes. */
    public static Path defaultDir(Map<String, String> environment, String home) {
        return CacheHome.folder(environment, home, "meshes");
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

    CacheFolder folder() {
        return folder;
    }

    long maxBytes() {
        return maxBytes;
    }

    /**
     * Looks for the entry of {@code obj} made with {@code options}, reading it whole: nothing of an
     * entry is used before all of it is checked, and an entry used is marked as used now. A stale
     * or damaged entry is a warning and counts as none; an OBJ file that cannot be read counts as
     * none, silently (its parse will say why); a small one is not looked up.
     */
    public MeshCacheLookup lookup(Path obj, String options, Consumer<String> warn) {
        ContentStamp stamp;
        try {
            if (uncompressedSize(obj) < minObjBytes) {
                return new MeshCacheLookup(this, obj, null, options, null, null, String.format(Locale.ROOT,
                    "smaller than %d KiB: parsed about as fast as read", minObjBytes / 1024));
            }
            stamp = ContentStamp.of(obj, "");
        } catch (IOException e) {
            return new MeshCacheLookup(this, obj, null, options, null, null, null);
        }
        Path file = dir.resolve(entryName(obj, stamp, options));
        if (!Files.isRegularFile(file)) {
            return new MeshCacheLookup(this, obj, file, options, stamp, null, null);
        }
        Path folder = obj.toAbsolutePath().getParent();
        try {
            MeshCacheEntry entry = MeshCacheFile.read(file, folder);
            String stale = stale(entry.header(), stamp, options, folder);
            if (stale == null) {
                CacheFolder.markUsed(file);
                return new MeshCacheLookup(this, obj, file, options, stamp, entry, null);
            }
            warn.accept("mesh cache " + file + " is stale (" + stale + "); " + obj.getFileName() + " is parsed again");
        } catch (MeshCacheFile.OtherVersion e) {
            // left by an older or newer program: rewritten below, as an entry never written would be
        } catch (IOException e) {
            warn.accept("mesh cache " + file + " is unusable (" + IoReason.of(e) + "); " + obj.getFileName()
                        + " is parsed again");
        }
        return new MeshCacheLookup(this, obj, file, options, stamp, null, null);
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
    private static String stale(MeshCacheHeader header, ContentStamp source, String options, Path folder) {
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

    /** {@code <name>-<key>.mesh}: the OBJ file's name and the key of its content's identity and the options. */
    static String entryName(Path obj, ContentStamp content, String options) {
        return EntryName.of(obj.getFileName().toString(), content.identity() + "\n" + options, "mesh");
    }
}

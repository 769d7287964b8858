package raytracer.cache;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import raytracer.accel.FlatBVH;
import raytracer.image.IoReason;
import raytracer.io.obj.ObjModel;
import raytracer.shapes.mesh.Mesh;

/**
 * One mesh file's place in the {@link MeshCache}: the entry found, read whole and checked
 * ({@link #take}, null when none is usable), or where to write one after building, or why there
 * is none.
 */
public final class MeshCacheLookup {
    private final MeshCache cache;
    private final Path obj;
    private final Path file;
    private final String options;
    private final ContentStamp source;
    private MeshCacheEntry entry;
    /** Why the mesh is not cached at all (too small), or null. */
    private final String notCached;

    MeshCacheLookup(MeshCache cache, Path obj, Path file, String options, ContentStamp source, MeshCacheEntry entry,
                    String notCached) {
        this.cache = cache;
        this.obj = obj;
        this.file = file;
        this.options = options;
        this.source = source;
        this.entry = entry;
        this.notCached = notCached;
    }

    /** What storing an entry did: written, with how many others were evicted to stay under the cap; or why not. */
    public record Stored(boolean written, int evicted, String whyNot) {
    }

    /** The usable entry's header, or null. */
    public MeshCacheHeader header() {
        return entry == null ? null : entry.header();
    }

    /** The entry's file (null when the mesh file could not be read, or is too small to be cached). */
    public Path file() {
        return file;
    }

    /** The usable entry, as read and checked when it was looked up; the lookup lets go of it. */
    public MeshCacheEntry take() {
        MeshCacheEntry taken = entry;
        entry = null;
        return taken;
    }

    /**
     * Writes the entry for {@code model} (its figures; its mesh may be gone) as built into
     * {@code mesh} and {@code bvh}, then keeps the cache under its cap; a small mesh, a model that
     * warned, an entry larger than the cap or a folder that cannot be written is not cached (the
     * last with a warning).
     */
    public Stored store(ObjModel model, Mesh mesh, FlatBVH bvh, Consumer<String> warn) {
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
        if (size > cache.maxBytes()) {
            return new Stored(false, 0, String.format(Locale.ROOT, "its entry of %.1f MiB is larger than the cache's cap of %.1f MiB",
                                                      size / 1048576.0, cache.maxBytes() / 1048576.0));
        }
        Path folder = obj.toAbsolutePath().getParent();
        try {
            List<ContentStamp> libraries = new ArrayList<>();
            for (Path library : model.libraries()) {
                libraries.add(ContentStamp.of(library, folder.relativize(library.toAbsolutePath().normalize()).toString()));
            }
            MeshCacheHeader h = new MeshCacheHeader(source, options, libraries, model.faces(), model.ngons(), mesh.vertexCount(),
                mesh.triangleCount(), mesh.hasNormals(), mesh.hasUvs(), mesh.materialIds() != null, mesh.bounds(), model.materials(),
                model.sheets());
            CacheFolder.Trimmed trimmed = cache.folder().store(file, MeshCacheFile.body(h, mesh, bvh, folder), cache.maxBytes());
            if (trimmed.failure() != null) {
                warn.accept("cannot keep the mesh cache " + cache.dir() + " under its cap (" + IoReason.of(trimmed.failure()) + ")");
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

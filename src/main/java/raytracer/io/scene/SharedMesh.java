package raytracer.io.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import raytracer.accel.FlatBVH;
import raytracer.accel.MedianSplitBuilder;
import raytracer.accel.MeshBVH;
import raytracer.accel.SahBuilder;
import raytracer.cache.MeshCache;
import raytracer.cache.MeshCacheEntry;
import raytracer.cache.MeshCacheHeader;
import raytracer.cache.MeshCacheLookup;
import raytracer.core.Material;
import raytracer.image.FileKind;
import raytracer.io.obj.ObjMaterial;
import raytracer.io.obj.ObjModel;
import raytracer.math.BBox;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.ParsedMesh;

/**
 * One OBJ file with one set of options (smoothing, builder), as every mesh object of a scene that
 * names them shares it: parsed or read from the mesh cache once ({@link #load}), its BVH built
 * once, its arrays held once (when each object held its own copy, 400 objects naming one
 * 40k-triangle file took 400 copies, and 1000 ran out of a 1 GiB heap). Each object puts its own
 * materials and normal maps around the shared arrays ({@link MeshBVH#inLeafOrder}); objects that
 * differ only by their transform share the object too ({@link MeshReader}), as instances of it. The frames of an animation share it as
 * well ({@link SceneFile}): what it reads and builds is reported to the frame that first needs it.
 */
final class SharedMesh {
    private final String name;
    private final String builder;
    /** The mesh file and the files it names (material libraries), which every scene using it reads. */
    private final List<Path> inputs;
    /** The mesh's place in the cache, or null without one. */
    private final MeshCacheLookup lookup;
    private final BBox bounds;
    private final List<ObjMaterial> materials;
    private final Set<Integer> sheets;
    /** The parse, until the tree is built over it; null when the mesh came from the cache. */
    private ObjModel model;
    private final long parseNanos;
    /** The cache entry as read at load, until it is taken; null when the mesh was parsed. */
    private MeshCacheEntry contents;
    private final long readNanos;
    /** The mesh in its tree's leaf order and the tree, once made. */
    private Mesh mesh;
    private FlatBVH bvh;

    /** A mesh parsed now, to be built when the scene is prepared. */
    private SharedMesh(Path file, String builder, MeshCacheLookup lookup, ObjModel model, long parseNanos, List<Path> inputs) {
        this.name = file.getFileName().toString();
        this.builder = builder;
        this.inputs = List.copyOf(inputs);
        this.lookup = lookup;
        this.model = model;
        this.parseNanos = parseNanos;
        this.readNanos = 0;
        this.bounds = model.parsed().bounds();
        this.materials = model.materials();
        this.sheets = model.sheets();
    }

    /** A mesh read whole from the cache now (checked), to be taken when the scene is prepared. */
    private SharedMesh(Path file, String builder, MeshCacheLookup lookup, long readNanos, List<Path> inputs) {
        this.name = file.getFileName().toString();
        this.builder = builder;
        this.inputs = List.copyOf(inputs);
        this.lookup = lookup;
        this.contents = lookup.take();
        this.readNanos = readNanos;
        this.parseNanos = 0;
        MeshCacheHeader header = contents.header();
        this.bounds = header.bounds();
        this.materials = header.materials();
        this.sheets = header.sheets();
    }

    /**
     * The mesh object {@code o}'s file: its entry read from {@code cache} (null: no cache), or the
     * file parsed, with the load report's figures and warnings.
     */
    static SharedMesh load(YamlObject o, Path file, boolean smooth, String builder, String options, MeshCache cache, LoadReport report)
            throws SceneException {
        String name = file.getFileName().toString();
        report.addInput(file);
        String notRegular = FileKind.notRegular(file);
        if (notRegular != null) {
            // before the cache's checksum of the file, which would block on a FIFO as a parse would
            throw o.source().error(o.raw("file"), "cannot read mesh " + file + ": " + notRegular);
        }
        long lookupStart = System.nanoTime();
        MeshCacheLookup lookup = cache == null ? null : cache.lookup(file, options, report::addWarning);
        long readNanos = System.nanoTime() - lookupStart;
        MeshCacheHeader cached = lookup == null ? null : lookup.header();
        if (cached != null) {
            report.addStatistic(MeshReader.statistic(name, cached.triangles(), cached.vertices(), cached.ngons(), cached.faces()));
            List<Path> inputs = new ArrayList<>(List.of(file));
            cached.libraries().forEach(library -> inputs.add(file.toAbsolutePath().getParent().resolve(library.path())));
            inputs.forEach(report::addInput);
            return new SharedMesh(file, builder, lookup, readNanos, inputs);
        }
        long start = System.nanoTime();
        ObjModel model = MeshReader.parse(o, file, smooth);
        long parseNanos = System.nanoTime() - start;
        report.recordTiming("parse " + name, parseNanos);
        model.warnings().forEach(report::addWarning);
        report.addStatistic(MeshReader.statistic(name, model.parsed().triangleCount(), model.parsed().vertexCount(), model.ngons(),
                                      model.faces()));
        model.libraries().forEach(report::addInput);
        List<Path> inputs = new ArrayList<>(List.of(file));
        inputs.addAll(model.libraries());
        return new SharedMesh(file, builder, lookup, model, parseNanos, inputs);
    }


    String name() {
        return name;
    }

    List<Path> inputs() {
        return inputs;
    }

    /** The box of the vertices, for the scene analysis before anything is built. */
    BBox bounds() {
        return bounds;
    }

    List<ObjMaterial> materials() {
        return materials;
    }

    Set<Integer> sheets() {
        return sheets;
    }

    /**
     * The mesh object for one scene object: its materials around the shared arrays and tree,
     * which the first call makes (reading them from the cache entry, or building the tree over
     * the parse and caching both, and telling {@code report} so) and later calls reuse.
     */
    synchronized MeshBVH objectWith(List<Material> objectMaterials, LoadReport report) {
        if (mesh == null) {
            if (contents != null) {
                take(report);
            } else {
                build(report);
            }
        }
        return MeshBVH.inLeafOrder(mesh, bvh, objectMaterials);
    }

    /**
     * The tree over the parsed mesh, and the mesh in its leaf order: either builder carries the
     * parse's own triangle array into that order with the triangles' float boxes, so no copy of
     * the mesh in file order is made.
     */
    private void buildTree(ParsedMesh parsed) {
        float[] boxes = MeshBVH.triangleBoxes(parsed);
        FlatBVH tree = builder.equals("median")
                       ? new MedianSplitBuilder(MeshReader.MEDIAN_LEAF_SIZE).build(boxes, parsed.triangles())
                       : new SahBuilder(MeshReader.SAH_MAX_LEAF_SIZE).build(boxes, parsed.triangles());
        mesh = parsed.afterTrianglesMoved(tree.leafOrder());
        bvh = tree.inLeafOrder();
    }

    private void take(LoadReport report) {
        long start = System.nanoTime();
        mesh = contents.mesh();
        bvh = contents.bvh();
        contents = null;
        long took = readNanos + System.nanoTime() - start;
        report.recordPrepareTiming("read " + name + " from the mesh cache", took);
        report.addStatistic(String.format("mesh %s: read from the mesh cache in %.3f s (%s)", name, took / 1e9, lookup.file()));
    }

    /**
     * Builds the tree over the parse and puts the mesh in the tree's leaf order (the time includes
     * the triangles' boxes and the renumbering), then caches both.
     */
    private void build(LoadReport report) {
        long start = System.nanoTime();
        buildTree(model.parsed());
        // the parse in file order is let go now: the cache entry is written from the leaf order
        model = model.withoutMesh();
        long built = System.nanoTime() - start;
        report.recordPrepareTiming(builder + " BVH of " + name + " (" + bvh.nodeCount() + " nodes)", built);
        String cached = "";
        if (lookup != null) {
            long write = System.nanoTime();
            MeshCacheLookup.Stored stored = lookup.store(model, mesh, bvh, report::addWarning);
            if (stored.written()) {
                long wrote = System.nanoTime() - write;
                report.recordPrepareTiming("write " + name + " to the mesh cache", wrote);
                cached = String.format(", written to the mesh cache in %.3f s", wrote / 1e9)
                         + (stored.evicted() == 0 ? "" : " (" + stored.evicted() + " least recently used entr"
                            + (stored.evicted() == 1 ? "y" : "ies") + " evicted to stay under the cache's cap)");
            } else if (stored.whyNot() != null) {
                cached = ", not cached (" + stored.whyNot() + ")";
            }
        }
        report.addStatistic(String.format("mesh %s: parsed in %.3f s, %s BVH built in %.3f s%s", name, parseNanos / 1e9,
                                          builder, built / 1e9, cached));
        model = null;
    }
}

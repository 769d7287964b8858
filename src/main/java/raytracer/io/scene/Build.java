package raytracer.io.scene;

import java.nio.file.Path;
import java.util.List;
import raytracer.accel.FlatBVH;
import raytracer.accel.MedianSplitBuilder;
import raytracer.accel.MeshBVH;
import raytracer.accel.SahBuilder;
import raytracer.core.Material;
import raytracer.io.obj.ObjModel;

/**
 * How a mesh object of the scene is made when it is prepared: read back from the mesh cache, or
 * its BVH built over the parsed mesh (and the result cached); each way says in the load report
 * what it took.
 */
final class Build {
    private final YamlObject object;
    private final Path file;
    private final boolean smooth;
    private final String builder;
    private final List<Material> materials;
    private final LoadReport report;
    /** The mesh's place in the cache, or null without one. */
    private final MeshCache.Lookup lookup;
    private final String name;

    Build(YamlObject object, Path file, boolean smooth, String builder, List<Material> materials, LoadReport report,
          MeshCache.Lookup lookup) {
        this.object = object;
        this.file = file;
        this.smooth = smooth;
        this.builder = builder;
        this.materials = materials;
        this.report = report;
        this.lookup = lookup;
        this.name = file.getFileName().toString();
    }

    /** The cached mesh and tree, read and checked whole when the scene was loaded. */
    MeshBVH fromCache(MeshCacheFile.Contents contents, long readNanos) {
        long start = System.nanoTime();
        MeshBVH mesh = MeshBVH.inLeafOrder(contents.mesh(), contents.bvh(), materials);
        long took = readNanos + System.nanoTime() - start;
        report.recordPrepareTiming("read " + name + " from the mesh cache", took);
        report.addStatistic(String.format("mesh %s: read from the mesh cache in %.3f s (%s)", name, took / 1e9, lookup.file()));
        return mesh;
    }

    /** Builds the tree over the parsed mesh (the time includes the triangles' boxes and renumbering them in leaf order), then caches both. */
    MeshBVH of(ObjModel model, long parseNanos) {
        long start = System.nanoTime();
        FlatBVH bvh = builder.equals("median")
            ? new MedianSplitBuilder(MeshReader.MEDIAN_LEAF_SIZE).build(MeshBVH.triangleBoxes(model.mesh()))
            : new SahBuilder(MeshReader.SAH_MAX_LEAF_SIZE).build(MeshBVH.triangleBounds(model.mesh()));
        MeshBVH mesh = new MeshBVH(model.mesh(), bvh, materials);
        long built = System.nanoTime() - start;
        report.recordPrepareTiming(builder + " BVH of " + name + " (" + bvh.nodeCount() + " nodes)", built);
        String cached = "";
        if (lookup != null) {
            long write = System.nanoTime();
            if (lookup.store(model, mesh, report::addWarning)) {
                long wrote = System.nanoTime() - write;
                report.recordPrepareTiming("write " + name + " to the mesh cache", wrote);
                cached = String.format(", written to the mesh cache in %.3f s", wrote / 1e9);
            } else if (!model.warnings().isEmpty()) {
                cached = ", not cached (its parse warned)";
            }
        }
        report.addStatistic(String.format("mesh %s: parsed in %.3f s, %s BVH built in %.3f s%s", name, parseNanos / 1e9,
                                          builder, built / 1e9, cached));
        return mesh;
    }
}

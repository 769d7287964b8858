package raytracer.accel;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Ray;
import raytracer.math.ShearedRay;
import raytracer.shapes.mesh.Mesh;
import raytracer.shapes.mesh.ParsedMesh;
import raytracer.shapes.mesh.TriangleMesh;

/**
 * A triangle mesh under a BVH, the scene object of a mesh: the tree finds the closest triangle,
 * keeping only t, the triangle and its barycentrics (the two-phase hit), and the
 * {@link TriangleMesh} tests the triangles of the leaves the ray reaches and completes the winner.
 * The mesh is renumbered in the tree's leaf order ({@link Mesh#reordered}): a leaf's triangles
 * are one run of its index array and their vertices lie together, so a leaf is read from a few
 * places in memory rather than from all over the mesh.
 */
public final class MeshBVH extends GeometricObject implements Leaves, StartedSearch {
    /** The corners of a triangle whose three vertices are the first three. */
    private static final int[] FIRST_THREE = {0, 1, 2};
    private final TriangleMesh mesh;
    private final FlatBVH bvh;
    /** The per-face materials, as given: what hits on this mesh may be shaded with besides its own. */
    private final List<Material> faceMaterials;

    /**
     * @param bvh       a tree built over the mesh's triangles, in the mesh's numbering
     * @param materials one per material id of the mesh (or one for all); null entries fall back to
     *                  this object's own material
     */
    public MeshBVH(Mesh mesh, FlatBVH bvh, List<Material> materials) {
        this(mesh, bvh, materials, false);
    }

    private MeshBVH(Mesh mesh, FlatBVH bvh, List<Material> materials, boolean inLeafOrder) {
        if (bvh.primitiveCount() != mesh.triangleCount()) {
            throw new IllegalArgumentException("the BVH was built for another mesh");
        }
        this.mesh = new TriangleMesh(inLeafOrder ? mesh : mesh.reordered(bvh.order), materials);
        this.bvh = bvh;
        this.faceMaterials = materials.stream().filter(Objects::nonNull).toList();
    }

    /**
     * A mesh already renumbered in {@code bvh}'s leaf order, as {@link #mesh()} gives it (the mesh
     * cache stores it so): no renumbering is done.
     */
    public static MeshBVH inLeafOrder(Mesh mesh, FlatBVH bvh, List<Material> materials) {
        return new MeshBVH(mesh, bvh, materials, true);
    }

    /** The bounds of every triangle, six numbers each, as the builders take them. */
    public static double[] triangleBounds(Mesh mesh) {
        double[] p = mesh.positions();
        double[] b = new double[6 * mesh.triangleCount()];
        for (int t = 0; t < mesh.triangleCount(); t++) {
            int a = mesh.corner(t, 0);
            int c1 = mesh.corner(t, 1);
            int c2 = mesh.corner(t, 2);
            for (int k = 0; k < 3; k++) {
                b[6 * t + k] = Math.min(p[a + k], Math.min(p[c1 + k], p[c2 + k]));
                b[6 * t + 3 + k] = Math.max(p[a + k], Math.max(p[c1 + k], p[c2 + k]));
            }
        }
        return b;
    }

    /**
     * The bounds of every triangle as floats rounded outward, six each, as
     * {@link MedianSplitBuilder#build(float[])} takes them: half the memory of doubles, and the
     * tree stores floats anyway.
     */
    public static float[] triangleBoxes(Mesh mesh) {
        double[] p = mesh.positions();
        int[] corners = mesh.triangles();
        float[] b = new float[6 * mesh.triangleCount()];
        for (int t = 0; t < mesh.triangleCount(); t++) {
            triangleBox(p, corners, t, b);
        }
        return b;
    }

    /** As {@link #triangleBoxes(Mesh)}, for a mesh as a loader read it. */
    public static float[] triangleBoxes(ParsedMesh mesh) {
        float[] b = new float[6 * mesh.triangleCount()];
        double[] corners = new double[9];
        for (int t = 0; t < mesh.triangleCount(); t++) {
            triangleBox(mesh, t, corners, b);
        }
        return b;
    }

    /** Triangle t's box, its corners gathered from the loader's blocks into {@code corners} first. */
    private static void triangleBox(ParsedMesh mesh, int t, double[] corners, float[] b) {
        for (int k = 0; k < 3; k++) {
            int at = mesh.corner(t, k);
            corners[3 * k] = mesh.position(at);
            corners[3 * k + 1] = mesh.position(at + 1);
            corners[3 * k + 2] = mesh.position(at + 2);
        }
        triangleBox(corners, FIRST_THREE, 0, b, 6 * t);
    }

    private static void triangleBox(double[] p, int[] corners, int t, float[] b) {
        triangleBox(p, corners, t, b, 6 * t);
    }

    private static void triangleBox(double[] p, int[] corners, int t, float[] b, int at) {
        // a method of its own: on a fresh JVM the JIT compiles it after a few hundred calls, where
        // a loop body waits for tens of thousands of iterations (the mesh is loaded once)
        int a = 3 * corners[3 * t];
        int c1 = 3 * corners[3 * t + 1];
        int c2 = 3 * corners[3 * t + 2];
        for (int k = 0; k < 3; k++) {
            double pa = p[a + k];
            double pb = p[c1 + k];
            double pc = p[c2 + k];
            b[at + k] = FloatBoxes.roundDownLoosely(pa < pb ? (pa < pc ? pa : pc) : (pb < pc ? pb : pc));
            b[at + 3 + k] = FloatBoxes.roundUpLoosely(pa > pb ? (pa > pc ? pa : pc) : (pb > pc ? pb : pc));
        }
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        sr.scratch.shearedRay.load(ray);
        return bvh.closestHit(ray, sr, this);
    }

    @Override
    public GeometricObject within(List<HalfSpace> volume) {
        return SubtreeSearch.of(this, bvh, volume);
    }

    @Override
    public boolean hit(FlatBVH.Start start, Ray ray, ShadeRec sr) {
        sr.scratch.shearedRay.load(ray);
        return bvh.closestHit(start, ray, sr, this);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        sr.scratch.shearedRay.load(ray);
        return bvh.anyHit(ray, tMax, sr, this);
    }

    @Override
    public boolean hit(int first, int count, Ray ray, ShadeRec sr) {
        ShearedRay sheared = sr.scratch.shearedRay;
        boolean hit = false;
        for (int tri = first; tri < first + count; tri++) {
            double t = mesh.intersect(tri, sheared, sr.t, sr);
            if (t < sr.t) {
                sr.recordHit(t, this);
                sr.primitive = tri;
                hit = true;
            }
        }
        return hit;
    }

    @Override
    public boolean shadowHit(int first, int count, Ray ray, double tMax, ShadeRec sr) {
        ShearedRay sheared = sr.scratch.shearedRay;
        for (int tri = first; tri < first + count; tri++) {
            if (mesh.blocks(tri, sheared, tMax)) {
                return true;
            }
        }
        return false;
    }

    /** Completes the hit on the triangle that won, numbered as in {@link #triangles()}. */
    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        mesh.completeHit(ray, sr);
    }

    @Override
    public BBox boundingBox() {
        return new BBox(bvh.rootBound(0), bvh.rootBound(1), bvh.rootBound(2),
                        bvh.rootBound(3), bvh.rootBound(4), bvh.rootBound(5));
    }

    /** The mesh's own material and its per-face ones. */
    @Override
    public List<Material> materials() {
        Set<Material> all = new LinkedHashSet<>(super.materials());
        all.addAll(faceMaterials);
        return List.copyOf(all);
    }

    public FlatBVH bvh() {
        return bvh;
    }

    /** The mesh with its triangles renumbered in the tree's leaf order: {@code sr.primitive} numbers them so. */
    public TriangleMesh triangles() {
        return mesh;
    }

    /** The mesh's data, triangles in leaf order as in {@link #triangles()}. */
    public Mesh mesh() {
        return mesh.mesh();
    }
}

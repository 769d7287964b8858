package raytracer.accel;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.BBox;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.shapes.Watertight;
import raytracer.shapes.mesh.Mesh;

/**
 * A triangle mesh under a BVH: one object for all its triangles (as Sunflow's mesh is). The search
 * visits the nearer child first and keeps only t, the triangle and its barycentrics; the winner's
 * normal and u/v are interpolated once in {@link #completeHit}.
 */
public final class MeshBVH extends GeometricObject implements Leaves {
    private final Mesh mesh;
    private final double[] positions;
    private final FlatBVH bvh;
    /**
     * The vertex offsets into {@link #positions} of each triangle's corners, in BVH leaf order: a
     * leaf's triangles are one contiguous run of indices (12 bytes a triangle; nine copied
     * coordinates took 72, and renumbering the vertices in leaf order as well measured no faster).
     */
    private final int[] leafCorners;
    private final Material[] materials;
    /** Per material id: a normal map (RGB = (n + 1) / 2) or null, and whether it is in tangent space. */
    private final Texture[] normalMaps;
    private final boolean[] tangentSpace;

    /**
     * @param materials one per material id of the mesh (or one for all); null entries fall back to
     *                  the object's own material
     */
    public MeshBVH(Mesh mesh, FlatBVH bvh, List<Material> materials) {
        if (bvh.primitiveCount() != mesh.triangleCount()) {
            throw new IllegalArgumentException("the BVH was built for another mesh");
        }
        this.mesh = mesh;
        this.positions = mesh.positions();
        this.bvh = bvh;
        this.materials = materials.toArray(new Material[0]);
        this.normalMaps = new Texture[Math.max(1, this.materials.length)];
        this.tangentSpace = new boolean[normalMaps.length];
        int[] order = bvh.order;
        int[] corners = mesh.triangles();
        leafCorners = new int[3 * order.length];
        for (int k = 0; k < 3 * order.length; k++) {
            leafCorners[k] = 3 * corners[3 * order[k / 3] + k % 3];
        }
    }

    /**
     * Gives the triangles of material {@code id} (0 when the mesh has one material) a normal map:
     * object space as in the report, or tangent space (OpenGL convention, green up) with tangents
     * from the texture coordinates.
     */
    public void setNormalMap(int id, Texture map, boolean tangent) {
        normalMaps[id] = map;
        tangentSpace[id] = tangent;
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
     * traversal stores floats anyway.
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

    /**
     * One triangle's box. A method of its own so that on a fresh JVM it is compiled after a few
     * hundred calls, while a loop body waits for tens of thousands of iterations before the JIT
     * replaces it (the mesh is loaded once, so this start-up phase is much of its cost).
     */
    private static void triangleBox(double[] p, int[] corners, int t, float[] b) {
        int a = 3 * corners[3 * t];
        int c1 = 3 * corners[3 * t + 1];
        int c2 = 3 * corners[3 * t + 2];
        for (int k = 0; k < 3; k++) {
            double pa = p[a + k];
            double pb = p[c1 + k];
            double pc = p[c2 + k];
            b[6 * t + k] = below(pa < pb ? (pa < pc ? pa : pc) : (pb < pc ? pb : pc));
            b[6 * t + 3 + k] = above(pa > pb ? (pa > pc ? pa : pc) : (pb > pc ? pb : pc));
        }
    }

    /**
     * A float not above d, without a branch: the float nearest to x is within 2^-24 |x| of it (or
     * 2^-150 below the normal range), so stepping down by 2^-22 |d| + 2^-149 first is enough. At
     * most a few float ulps below d, where {@link FlatBVH#roundDown} is exact but branches on
     * which way the cast went.
     */
    static float below(double d) {
        return (float) Math.min(d - (Math.abs(d) * 0x1p-22 + Float.MIN_VALUE), Float.MAX_VALUE);
    }

    /** A float not below d, as {@link #below}. */
    static float above(double d) {
        return (float) Math.max(d + (Math.abs(d) * 0x1p-22 + Float.MIN_VALUE), -Float.MAX_VALUE);
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return bvh.closestHit(ray, sr, this);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return bvh.anyHit(ray, tMax, sr, this);
    }

    @Override
    public boolean hit(int first, int count, Ray ray, ShadeRec sr) {
        boolean hit = false;
        for (int k = first; k < first + count; k++) {
            double t = Watertight.intersect(ray, positions, leafCorners[3 * k], leafCorners[3 * k + 1],
                                            leafCorners[3 * k + 2], sr.t, sr);
            if (t < sr.t) {
                sr.recordHit(t, this);
                sr.primitive = bvh.order[k];
                hit = true;
            }
        }
        return hit;
    }

    @Override
    public boolean shadowHit(int first, int count, Ray ray, double tMax, ShadeRec sr) {
        for (int k = first; k < first + count; k++) {
            if (Watertight.intersect(ray, positions, leafCorners[3 * k], leafCorners[3 * k + 1],
                                     leafCorners[3 * k + 2], tMax, sr) < tMax) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        int tri = sr.primitive;
        double b1 = sr.b1;
        double b2 = sr.b2;
        double b0 = 1 - b1 - b2;
        int a = mesh.corner(tri, 0);
        int b = mesh.corner(tri, 1);
        int c = mesh.corner(tri, 2);
        Watertight.interpolate(positions, a, b, c, b0, b1, b2, sr);
        double[] p = positions;
        double e1x = p[b] - p[a];
        double e1y = p[b + 1] - p[a + 1];
        double e1z = p[b + 2] - p[a + 2];
        double e2x = p[c] - p[a];
        double e2y = p[c + 1] - p[a + 1];
        double e2z = p[c + 2] - p[a + 2];
        sr.geometricNormal.set(e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x);
        if (mesh.hasNormals()) {
            float[] n = mesh.normals();
            int va = 3 * mesh.vertex(tri, 0);
            int vb = 3 * mesh.vertex(tri, 1);
            int vc = 3 * mesh.vertex(tri, 2);
            sr.normal.set(b0 * n[va] + b1 * n[vb] + b2 * n[vc], b0 * n[va + 1] + b1 * n[vb + 1] + b2 * n[vc + 1],
                          b0 * n[va + 2] + b1 * n[vb + 2] + b2 * n[vc + 2]);
            if (!(sr.normal.length() > 0)) {
                sr.normal.set(sr.geometricNormal);
            } else if (sr.normal.dot(sr.geometricNormal) < 0) {
                // vertex normals say which side is out; keep the geometric normal on that side
                sr.geometricNormal.negate();
            }
        } else {
            sr.normal.set(sr.geometricNormal);
        }
        if (mesh.hasUvs()) {
            float[] uv = mesh.uvs();
            int ta = 2 * mesh.vertex(tri, 0);
            int tb = 2 * mesh.vertex(tri, 1);
            int tc = 2 * mesh.vertex(tri, 2);
            sr.u = b0 * uv[ta] + b1 * uv[tb] + b2 * uv[tc];
            sr.v = b0 * uv[ta + 1] + b1 * uv[tb + 1] + b2 * uv[tc + 1];
        } else {
            sr.u = b1;
            sr.v = b2;
        }
        int[] ids = mesh.materialIds();
        int id = ids != null ? ids[tri] : 0;
        if (id < normalMaps.length && normalMaps[id] != null) {
            applyNormalMap(tri, id, sr);
        }
        if (ids != null && ids[tri] < materials.length && materials[ids[tri]] != null) {
            sr.material = materials[ids[tri]];
        } else if (ids == null && materials.length == 1 && materials[0] != null) {
            sr.material = materials[0];
        }
    }

    /**
     * Replaces the shading normal by the map's: n = 2 rgb - 1, taken as it is (object space) or in
     * the frame (T, B, N) where T and B follow u and v across the triangle (tangent space).
     */
    private void applyNormalMap(int tri, int id, ShadeRec sr) {
        MutableRgb texel = sr.scratch.brdfScratch;
        normalMaps[id].getColor(sr, texel);
        double mx = 2 * texel.r - 1;
        double my = 2 * texel.g - 1;
        double mz = 2 * texel.b - 1;
        if (!tangentSpace[id]) {
            sr.normal.set(mx, my, mz);
            return;
        }
        if (!mesh.hasUvs()) {
            return;
        }
        float[] uv = mesh.uvs();
        int a = mesh.corner(tri, 0);
        int b = mesh.corner(tri, 1);
        int c = mesh.corner(tri, 2);
        int ta = 2 * mesh.vertex(tri, 0);
        int tb = 2 * mesh.vertex(tri, 1);
        int tc = 2 * mesh.vertex(tri, 2);
        double du1 = uv[tb] - uv[ta];
        double dv1 = uv[tb + 1] - uv[ta + 1];
        double du2 = uv[tc] - uv[ta];
        double dv2 = uv[tc + 1] - uv[ta + 1];
        double det = du1 * dv2 - du2 * dv1;
        if (det == 0) {
            return; // no texture-space direction to follow
        }
        double[] p = positions;
        // dP/du from the two edges (Lengyel, "Computing tangent space basis vectors", 2001)
        double tx = ((p[b] - p[a]) * dv2 - (p[c] - p[a]) * dv1) / det;
        double ty = ((p[b + 1] - p[a + 1]) * dv2 - (p[c + 1] - p[a + 1]) * dv1) / det;
        double tz = ((p[b + 2] - p[a + 2]) * dv2 - (p[c + 2] - p[a + 2]) * dv1) / det;
        MutableVec3 n = sr.normal.normalize();
        // Gram-Schmidt: T perpendicular to N, B = N x T, flipped where the UVs are mirrored
        double tn = tx * n.x + ty * n.y + tz * n.z;
        tx -= tn * n.x;
        ty -= tn * n.y;
        tz -= tn * n.z;
        double len = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (!(len > 0)) {
            return;
        }
        tx /= len;
        ty /= len;
        tz /= len;
        double handedness = det < 0 ? -1 : 1;
        double bx = handedness * (n.y * tz - n.z * ty);
        double by = handedness * (n.z * tx - n.x * tz);
        double bz = handedness * (n.x * ty - n.y * tx);
        sr.normal.set(mx * tx + my * bx + mz * n.x, mx * ty + my * by + mz * n.y, mx * tz + my * bz + mz * n.z);
    }

    @Override
    public BBox boundingBox() {
        return new BBox(bvh.rootBound(0), bvh.rootBound(1), bvh.rootBound(2),
                        bvh.rootBound(3), bvh.rootBound(4), bvh.rootBound(5));
    }

    public FlatBVH bvh() {
        return bvh;
    }

    public Mesh mesh() {
        return mesh;
    }
}

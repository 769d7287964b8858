package raytracer.shapes.mesh;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.BBox;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.ShearedRay;
import raytracer.math.MutableVec3;
import raytracer.shapes.Watertight;

/**
 * A triangle mesh as one object over the flat arrays of a {@link Mesh} (as Sunflow's is): the
 * watertight test of one triangle by its index, and the completion of a hit with the normal and
 * texture coordinates interpolated across the triangle, its material and its normal map. On its
 * own it tests every triangle, as a list would; {@code accel.MeshBVH} searches it through a BVH,
 * testing only the triangles in the leaves a ray reaches.
 */
public final class TriangleMesh extends GeometricObject {
    private final Mesh mesh;
    private final double[] positions;
    private final int[] triangles;
    private final Material[] materials;
    /** Per material id: a normal map (RGB = (n + 1) / 2) or null, and whether it is in tangent space. */
    private final Texture[] normalMaps;
    private final boolean[] tangentSpace;

    /**
     * @param materials one per material id of the mesh (or one for all); null entries fall back to
     *                  the material of the object that was hit
     */
    public TriangleMesh(Mesh mesh, List<Material> materials) {
        this.mesh = mesh;
        this.positions = mesh.positions();
        this.triangles = mesh.triangles();
        this.materials = materials.toArray(new Material[0]);
        this.normalMaps = new Texture[Math.max(1, this.materials.length)];
        this.tangentSpace = new boolean[normalMaps.length];
    }

    public Mesh mesh() {
        return mesh;
    }

    public int triangleCount() {
        return mesh.triangleCount();
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

    /**
     * The distance to triangle {@code tri} if it lies in (0, tMax), with its barycentrics in
     * {@code sr}; otherwise +infinity ({@link Watertight#intersect}).
     */
    public double intersect(int tri, ShearedRay ray, double tMax, ShadeRec sr) {
        int[] t = triangles;
        return Watertight.intersect(ray, positions, 3 * t[3 * tri], 3 * t[3 * tri + 1], 3 * t[3 * tri + 2], tMax, sr);
    }

    /** True when the shadow ray certainly crosses triangle {@code tri} in (0, tMax) ({@link Watertight#crossesWithin}). */
    public boolean blocks(int tri, ShearedRay ray, double tMax) {
        int[] t = triangles;
        return Watertight.crossesWithin(ray, positions, 3 * t[3 * tri], 3 * t[3 * tri + 1], 3 * t[3 * tri + 2], tMax);
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        ShearedRay sheared = sr.scratch.shearedRay.load(ray);
        boolean hit = false;
        for (int tri = 0; tri < mesh.triangleCount(); tri++) {
            double t = intersect(tri, sheared, sr.t, sr);
            if (t < sr.t) {
                sr.recordHit(t, this);
                sr.primitive = tri;
                hit = true;
            }
        }
        return hit;
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        ShearedRay sheared = sr.scratch.shearedRay.load(ray);
        for (int tri = 0; tri < mesh.triangleCount(); tri++) {
            if (blocks(tri, sheared, tMax)) {
                return true;
            }
        }
        return false;
    }

    /** Completes the hit on triangle {@code sr.primitive} at barycentrics ({@code sr.b1}, {@code sr.b2}). */
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
        return mesh.bounds();
    }
}

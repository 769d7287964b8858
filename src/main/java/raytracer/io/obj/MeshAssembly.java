package raytracer.io.obj;

import java.util.Arrays;
import raytracer.shapes.mesh.Growing;
import raytracer.shapes.mesh.ParsedMesh;
import raytracer.shapes.mesh.SmoothNormals;

/**
 * Turns the parsed corner triples into a {@link ParsedMesh}: as is when corners are positions only,
 * otherwise one mesh vertex per distinct (v, vt, vn) triple, numbered in the order the corners
 * first name them. The triples are found with an open-addressing table of mesh vertex numbers,
 * kept at most half full, whose keys are the mesh vertices' own (v, vt, vn): 4 to 8 bytes a
 * slot rather than a copy of every corner's key (a table of twice the corners, with three ints
 * of key a slot, took 128 bytes per triangle).
 */
final class MeshAssembly {
    private MeshAssembly() {
    }

    static ParsedMesh build(ObjArrays parsed, boolean smoothNormals) {
        int[] materialIds = parsed.materialIds();
        if (parsed.cornerVt() == null && parsed.cornerVn() == null) {
            int[] v = parsed.cornerV().toArray();
            float[] normals = smoothNormals ? SmoothNormals.angleWeighted(parsed.positions(), v) : null;
            return new ParsedMesh(parsed.positions(), normals, null, v, materialIds);
        }
        Triples triples = new Triples(parsed);
        Growing.Ints v = parsed.cornerV();
        Growing.Ints vt = parsed.cornerVt();
        Growing.Ints vn = parsed.cornerVn();
        int[] triangles = new int[v.size()];
        for (int c = 0; c < triangles.length; c++) {
            triangles[c] = triples.vertex(v.get(c), vt != null ? vt.get(c) : -1, vn != null ? vn.get(c) : -1);
        }
        float[] normals = vn != null ? triples.normals.toArray()
                        : smoothNormals ? SmoothNormals.angleWeighted(triples.positions, triangles) : null;
        float[] uvs = vt != null ? triples.uvs.toArray() : null;
        return new ParsedMesh(triples.positions, normals, uvs, triangles, materialIds);
    }

    /** The mesh vertices made so far, one per distinct (v, vt, vn), and the table that finds them. */
    private static final class Triples {
        private final Growing.Doubles filePositions;
        private final Growing.Floats fileUvs;
        private final Growing.Floats fileNormals;
        private final boolean withUvs;
        private final boolean withNormals;
        /** Per mesh vertex: its triple. */
        private final Growing.Ints keyV = new Growing.Ints();
        private final Growing.Ints keyVt = new Growing.Ints();
        private final Growing.Ints keyVn = new Growing.Ints();
        /** Per mesh vertex: its values. */
        final Growing.Doubles positions = new Growing.Doubles();
        final Growing.Floats uvs = new Growing.Floats();
        final Growing.Floats normals = new Growing.Floats();
        /** Mesh vertex numbers by hash of their triple, -1 where empty. */
        private int[] slots = new int[1024];
        private int made;

        Triples(ObjArrays parsed) {
            filePositions = parsed.positions();
            fileUvs = parsed.texcoords();
            fileNormals = parsed.normals();
            withUvs = parsed.cornerVt() != null;
            withNormals = parsed.cornerVn() != null;
            Arrays.fill(slots, -1);
        }

        /** The mesh vertex of the triple (v, vt, vn), made when it is new; -1 stands for an absent vt or vn. */
        int vertex(int v, int vt, int vn) {
            int mask = slots.length - 1;
            int slot = hash(v, vt, vn) & mask;
            for (int m = slots[slot]; m >= 0; m = slots[slot]) {
                if (keyV.get(m) == v && keyVt.get(m) == vt && keyVn.get(m) == vn) {
                    return m;
                }
                slot = (slot + 1) & mask;
            }
            int m = made++;
            slots[slot] = m;
            keyV.add(v);
            keyVt.add(vt);
            keyVn.add(vn);
            for (int k = 0; k < 3; k++) {
                positions.add(filePositions.get(3 * v + k));
            }
            if (withUvs) {
                uvs.add(vt >= 0 ? fileUvs.get(2 * vt) : 0f);
                uvs.add(vt >= 0 ? fileUvs.get(2 * vt + 1) : 0f);
            }
            for (int k = 0; withNormals && k < 3; k++) {
                // a corner without vn in a file that has them: zero, the renderer then uses the face normal
                normals.add(vn >= 0 ? fileNormals.get(3 * vn + k) : 0f);
            }
            if (2 * made > slots.length) {
                rehash();
            }
            return m;
        }

        private void rehash() {
            slots = new int[2 * slots.length];
            Arrays.fill(slots, -1);
            int mask = slots.length - 1;
            for (int m = 0; m < made; m++) {
                int slot = hash(keyV.get(m), keyVt.get(m), keyVn.get(m)) & mask;
                while (slots[slot] >= 0) {
                    slot = (slot + 1) & mask;
                }
                slots[slot] = m;
            }
        }

        private static int hash(int v, int vt, int vn) {
            return (int) ((v * 0x9E3779B1L) ^ (vt * 0x85EBCA77L) ^ (vn * 0xC2B2AE3DL));
        }
    }
}

package raytracer.cache;

import java.io.IOException;
import raytracer.accel.BvhFile;
import raytracer.accel.FlatBVH;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Mesh;

/**
 * A mesh cache entry's parts as {@link MeshCacheFile#read} reads them, before {@link #check}: the
 * header, then the arrays it counts, filled as the bytes arrive and checked against each other
 * only once the whole file has passed its checksum.
 */
final class MeshCacheParts {
    private final MeshCacheHeader header;
    private double[] positions;
    private float[] normals;
    private float[] uvs;
    private int[] triangles;
    private int[] ids;
    private FlatBVH bvh;

    MeshCacheParts(MeshCacheHeader header) {
        this.header = header;
    }

    /** Reads the arrays the header counts, sized from it once they are known to fit the file. */
    void read(ChecksummedInput in, long size) throws IOException {
        if (24L * header.vertices() + 12L * header.triangles() > size) {
            throw new IOException("its header counts more vertices and triangles than it holds");
        }
        positions = new double[3 * header.vertices()];
        in.getDoubles(positions);
        normals = header.normals() ? getFloats(in, 3 * header.vertices()) : null;
        uvs = header.uvs() ? getFloats(in, 2 * header.vertices()) : null;
        triangles = getInts(in, 3 * header.triangles());
        ids = header.materialIds() ? getInts(in, header.triangles()) : null;
        bvh = BvhFile.read(in);
        in.align();
        if (in.remaining() != 0) {
            throw new IOException("it holds " + in.remaining() + " bytes more than its header counts");
        }
    }

    /** The parts checked against each other, as a whole entry. */
    MeshCacheEntry check() throws IOException {
        requireFinite(positions, "vertex");
        requireFinite(normals, "normal");
        requireFinite(uvs, "texture coordinate");
        Mesh mesh = new Mesh(positions, normals, uvs, triangles, ids);
        if (!mesh.bounds().equals(header.bounds())) {
            throw new IOException("its header's bounds " + header.bounds() + " are not its vertices' " + mesh.bounds());
        }
        if (ids != null) {
            int materials = Math.max(1, header.materials().size());
            for (int id : ids) {
                if (id < 0 || id >= materials) {
                    throw new IOException("a triangle has material id " + id + " of " + materials);
                }
            }
        }
        if (bvh.primitiveCount() != header.triangles()) {
            throw new IOException("its tree holds " + bvh.primitiveCount() + " triangles of " + header.triangles());
        }
        if (bvh.leafOrder() != null) {
            throw new IOException("its tree is not in the mesh's order");
        }
        return new MeshCacheEntry(header, mesh, bvh);
    }

    /** Vertex coordinates: finite and within what a triangle holds ({@link Triangle#MAX_COORDINATE}), as the OBJ reader requires. */
    private static void requireFinite(double[] values, String what) throws IOException {
        for (double v : values) {
            if (!(Math.abs(v) <= Triangle.MAX_COORDINATE)) {
                throw new IOException("a " + what + " coordinate is " + v);
            }
        }
    }

    private static void requireFinite(float[] values, String what) throws IOException {
        if (values != null) {
            for (float v : values) {
                if (!Float.isFinite(v)) {
                    throw new IOException("a " + what + " is not finite");
                }
            }
        }
    }


    private static float[] getFloats(ChecksummedInput in, int n) {
        float[] values = new float[n];
        in.getFloats(values);
        in.align();
        return values;
    }

    private static int[] getInts(ChecksummedInput in, int n) {
        int[] values = new int[n];
        in.getInts(values);
        in.align();
        return values;
    }
}

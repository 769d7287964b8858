package raytracer.cache;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import raytracer.cache.ContentStamp;
import raytracer.io.obj.ObjMaterial;
import raytracer.math.BBox;

/**
 * What a mesh cache file says before its arrays: the OBJ and the MTL files it was made from, the
 * options it was made with, the figures --stats prints, the mesh's exact bounds (for the scene
 * analysis), its MTL materials and which of them are open sheets ({@link raytracer.io.obj.ObjModel#sheets});
 * and its bytes ({@link java.io.DataOutput} form), apart from {@link MeshCacheFile} so that the
 * layout of the arrays reads on its own.
 */
public record MeshCacheHeader(ContentStamp source, String options, List<ContentStamp> libraries, int faces, int ngons, int vertices,
                              int triangles, boolean normals, boolean uvs, boolean materialIds, BBox bounds,
                              List<ObjMaterial> materials, Set<Integer> sheets) {

    /** The header's bytes; texture paths are written relative to {@code folder}, the OBJ file's. */
    byte[] encode(Path folder) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        writeStamp(out, source);
        out.writeUTF(options);
        out.writeInt(libraries.size());
        for (ContentStamp library : libraries) {
            writeStamp(out, library);
        }
        out.writeInt(faces);
        out.writeInt(ngons);
        out.writeInt(vertices);
        out.writeInt(triangles);
        out.writeBoolean(normals);
        out.writeBoolean(uvs);
        out.writeBoolean(materialIds);
        for (double v : new double[] {bounds.x0(), bounds.y0(), bounds.z0(), bounds.x1(), bounds.y1(), bounds.z1()}) {
            out.writeDouble(v);
        }
        out.writeInt(materials.size());
        for (ObjMaterial m : materials) {
            writeMaterial(out, m, folder);
        }
        out.writeInt(sheets.size());
        for (int id : sheets) {
            out.writeInt(id);
        }
        out.flush();
        return bytes.toByteArray();
    }

    /** The header of its bytes; texture paths are resolved against {@code folder}, the OBJ file's now. */
    static MeshCacheHeader decode(byte[] head, Path folder) throws IOException {
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(head));
        ContentStamp source = readStamp(in);
        String options = in.readUTF();
        List<ContentStamp> libraries = new ArrayList<>();
        for (int i = count(in); i > 0; i--) {
            libraries.add(readStamp(in));
        }
        int faces = in.readInt();
        int ngons = in.readInt();
        int vertices = in.readInt();
        int triangles = in.readInt();
        boolean normals = in.readBoolean();
        boolean uvs = in.readBoolean();
        boolean ids = in.readBoolean();
        BBox bounds = new BBox(in.readDouble(), in.readDouble(), in.readDouble(), in.readDouble(), in.readDouble(),
                               in.readDouble());
        List<ObjMaterial> materials = new ArrayList<>();
        for (int i = count(in); i > 0; i--) {
            materials.add(readMaterial(in, folder));
        }
        Set<Integer> sheets = new TreeSet<>();
        for (int i = count(in); i > 0; i--) {
            int id = in.readInt();
            if (id < 0 || id >= materials.size()) {
                throw new IOException("its header names material " + id + " of " + materials.size() + " as a sheet");
            }
            sheets.add(id);
        }
        if (vertices < 0 || triangles < 1) {
            throw new IOException("its header counts " + vertices + " vertices and " + triangles + " triangles");
        }
        return new MeshCacheHeader(source, options, libraries, faces, ngons, vertices, triangles, normals, uvs, ids, bounds,
                          materials, Set.copyOf(sheets));
    }

    private static int count(DataInputStream in) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > 1 << 20) {
            throw new IOException("its header lists " + n + " entries");
        }
        return n;
    }

    private static void writeMaterial(DataOutputStream out, ObjMaterial m, Path folder) throws IOException {
        out.writeUTF(m.name());
        for (double[] color : new double[][] {m.kd(), m.ks(), m.ka(), m.ke()}) {
            for (int k = 0; k < 3; k++) {
                out.writeDouble(color[k]);
            }
        }
        out.writeDouble(m.ns());
        out.writeDouble(m.dissolve());
        out.writeDouble(m.ior());
        out.writeInt(m.illum());
        out.writeUTF(relative(m.mapKd(), folder));
        out.writeUTF(relative(m.mapBump(), folder));
        out.writeDouble(m.bumpScale());
    }

    /** A texture's path relative to the OBJ file's folder, so that a copy of the files elsewhere finds its own; "" for none. */
    private static String relative(Path texture, Path folder) {
        return texture == null ? "" : folder.relativize(texture.toAbsolutePath().normalize()).toString();
    }

    private static Path resolved(String texture, Path folder) {
        return texture.isEmpty() ? null : folder.resolve(texture).normalize();
    }

    private static ObjMaterial readMaterial(DataInputStream in, Path folder) throws IOException {
        String name = in.readUTF();
        double[][] colors = new double[4][3];
        for (double[] color : colors) {
            for (int k = 0; k < 3; k++) {
                color[k] = in.readDouble();
            }
        }
        double ns = in.readDouble();
        double dissolve = in.readDouble();
        double ior = in.readDouble();
        int illum = in.readInt();
        String mapKd = in.readUTF();
        String mapBump = in.readUTF();
        return new ObjMaterial(name, colors[0], colors[1], colors[2], colors[3], ns, dissolve, ior, illum,
                               resolved(mapKd, folder), resolved(mapBump, folder),
                               in.readDouble());
    }

    private static void writeStamp(DataOutputStream out, ContentStamp s) throws IOException {
        out.writeUTF(s.path());
        out.writeLong(s.size());
        out.writeLong(s.digest());
    }

    private static ContentStamp readStamp(DataInputStream in) throws IOException {
        return new ContentStamp(in.readUTF(), in.readLong(), in.readLong());
    }
}

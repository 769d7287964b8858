package raytracer.io.scene;

import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Set;
import java.util.zip.CRC32;
import java.util.zip.CRC32C;
import raytracer.accel.BvhFile;
import raytracer.accel.FlatBVH;
import raytracer.image.AtomicFile;
import raytracer.io.obj.ObjMaterial;
import raytracer.math.BBox;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Mesh;

/**
 * The mesh cache's file: a parsed mesh, renumbered in its BVH's leaf order, and the BVH, in bytes
 * that are copied into the arrays in bulk. Little-endian throughout:
 *
 * <pre>
 *   long magic "RTMESH", int {@link #VERSION}, int {@link BvhFile#VERSION}, long file length
 *   int header length, header ({@link Header}, written by {@link MeshCacheHeader})
 *   double[3 v] positions, float[3 v] normals?, float[2 v] uvs?, int[3 t] triangles, int[t] material ids?
 *   the BVH ({@link BvhFile}), each array starting on a multiple of 8
 *   int CRC-32C of every byte before it
 * </pre>
 *
 * An entry is read whole, once, and nothing of it is used before its length, its checksum and the
 * consistency of every part with the others have been checked ({@link #read}).
 */
final class MeshCacheFile {
    /**
     * The layout above and what the OBJ reader and {@link MeshReader} make of a file: add 1 when
     * either changes, so that files written before are rebuilt rather than trusted.
     */
    static final int VERSION = 4;
    private static final long MAGIC = 0x0000_4853_454d_5452L; // "RTMESH\0\0" little-endian
    private static final int PREAMBLE = 8 + 4 + 4 + 8 + 4;

    private MeshCacheFile() {
    }

    /**
     * The identity of a file a cached mesh was made from: its content (size, and CRC-32C and CRC-32
     * of its bytes as one 64-bit digest) and, for an MTL file, its path relative to the OBJ file's
     * folder (empty for the OBJ file itself, which the entry's name finds by content).
     */
    record Stamp(String path, long size, long digest) {
    }

    /**
     * What a cache file says before its arrays: the OBJ and the MTL files it was made from, the
     * options it was made with, the figures --stats prints, the mesh's exact bounds (for the scene
     * analysis), its MTL materials and which of them are open sheets ({@link raytracer.io.obj.ObjModel#sheets}).
     */
    record Header(Stamp source, String options, List<Stamp> libraries, int faces, int ngons, int vertices,
                  int triangles, boolean normals, boolean uvs, boolean materialIds, BBox bounds,
                  List<ObjMaterial> materials, Set<Integer> sheets) {
    }

    /** A whole entry as read back and checked: its header, its mesh (in leaf order) and its tree. */
    record Contents(Header header, Mesh mesh, FlatBVH bvh) {
    }

    /** Bytes of an entry of {@code mesh} and {@code bvh}, but for its header (a few hundred bytes more). */
    static long size(Mesh mesh, FlatBVH bvh) {
        return align(PREAMBLE) + arrays(mesh) + align(BvhFile.size(bvh)) + 4;
    }

    /**
     * Writes the file atomically (temporary file and rename); texture paths are written relative
     * to {@code folder}, the OBJ file's.
     */
    static void write(Path file, Header header, Mesh mesh, FlatBVH bvh, Path folder) throws IOException {
        byte[] head = MeshCacheHeader.encode(header, folder);
        long length = align(PREAMBLE + head.length) + arrays(mesh) + align(BvhFile.size(bvh)) + 4;
        if (length > Integer.MAX_VALUE - 8) {
            throw new IOException("the mesh is too large to cache (" + length + " bytes)");
        }
        ByteBuffer out = ByteBuffer.allocate((int) length).order(ByteOrder.LITTLE_ENDIAN);
        out.putLong(MAGIC).putInt(VERSION).putInt(BvhFile.VERSION).putLong(length).putInt(head.length).put(head);
        pad(out);
        out.asDoubleBuffer().put(mesh.positions());
        out.position(out.position() + 8 * mesh.positions().length);
        putFloats(out, mesh.normals());
        putFloats(out, mesh.uvs());
        putInts(out, mesh.triangles());
        putInts(out, mesh.materialIds());
        BvhFile.write(bvh, out);
        pad(out);
        CRC32C crc = new CRC32C();
        crc.update(out.array(), 0, out.position());
        out.putInt((int) crc.getValue());
        AtomicFile.replace(file, stream -> stream.write(out.array(), 0, out.position()));
    }

    /**
     * The whole file, read once (one open, one read: an entry replaced meanwhile cannot mix two
     * versions) and checked before any of it is used: its length and checksum first, then the
     * header's counts against the arrays, the bounds against the vertices, every value finite,
     * every index and material id in range, the tree's links. An IOException says why the file is
     * not one this program can use.
     */
    static Contents read(Path file, Path folder) throws IOException {
        ByteBuffer in;
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = channel.size();
            if (size < PREAMBLE + 4 || size > Integer.MAX_VALUE - 8) {
                throw new IOException("it has " + size + " bytes");
            }
            in = ByteBuffer.allocateDirect((int) size).order(ByteOrder.LITTLE_ENDIAN);
            readFully(channel, in);
            if (channel.read(ByteBuffer.allocate(1)) > 0) {
                throw new IOException("it grew while it was read");
            }
        }
        int size = in.limit();
        // the preamble only chooses the message of a file refused anyway: another format, cut short
        checkPreamble(in, size);
        CRC32C crc = new CRC32C();
        crc.update(in.duplicate().position(0).limit(size - 4));
        if ((int) crc.getValue() != in.getInt(size - 4)) {
            throw new IOException("its checksum does not match its contents");
        }
        try {
            return decode(in, size, folder);
        } catch (IllegalArgumentException | IndexOutOfBoundsException | BufferUnderflowException e) {
            throw new IOException("its contents are inconsistent (" + e.getMessage() + ")", e);
        }
    }

    /** The header and arrays of a file whose checksum matched, each checked against the others. */
    private static Contents decode(ByteBuffer in, int size, Path folder) throws IOException {
        int headerLength = checkPreamble(in, size);
        byte[] head = new byte[headerLength];
        in.get(head);
        Header header = MeshCacheHeader.decode(head, folder);
        if (24L * header.vertices() + 12L * header.triangles() > size) {
            throw new IOException("its header counts more vertices and triangles than it holds");
        }
        in.position(align(in.position()));
        double[] positions = new double[3 * header.vertices()];
        in.asDoubleBuffer().get(positions);
        in.position(in.position() + 8 * positions.length);
        float[] normals = header.normals() ? getFloats(in, 3 * header.vertices()) : null;
        float[] uvs = header.uvs() ? getFloats(in, 2 * header.vertices()) : null;
        int[] triangles = getInts(in, 3 * header.triangles());
        int[] ids = header.materialIds() ? getInts(in, header.triangles()) : null;
        FlatBVH bvh = BvhFile.read(in);
        in.position(align(in.position()));
        if (in.position() != size - 4) {
            throw new IOException("it holds " + (size - 4 - in.position()) + " bytes more than its header counts");
        }
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
        return new Contents(header, mesh, bvh);
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

    /** Checks magic, versions and length; returns the header's length, with the buffer just past the preamble. */
    private static int checkPreamble(ByteBuffer in, long fileSize) throws IOException {
        in.position(0);
        if (in.getLong() != MAGIC) {
            throw new IOException("it is not a mesh cache file");
        }
        int version = in.getInt();
        int bvhVersion = in.getInt();
        if (version != VERSION || bvhVersion != BvhFile.VERSION) {
            throw new IOException("it was written by another version (format " + version + ", BVH " + bvhVersion
                                  + "; this program reads format " + VERSION + ", BVH " + BvhFile.VERSION + ")");
        }
        long length = in.getLong();
        if (length != fileSize) {
            throw new IOException("it is truncated or overlong (" + fileSize + " bytes of " + length + ")");
        }
        int headerLength = in.getInt();
        if (headerLength < 0 || PREAMBLE + (long) headerLength > fileSize) {
            throw new IOException("its header length " + headerLength + " is impossible");
        }
        return headerLength;
    }

    /** Bytes of the mesh's arrays, each padded to a multiple of 8. */
    private static long arrays(Mesh mesh) {
        long bytes = 8L * mesh.positions().length + align(4L * mesh.triangles().length);
        bytes += mesh.normals() == null ? 0 : align(4L * mesh.normals().length);
        bytes += mesh.uvs() == null ? 0 : align(4L * mesh.uvs().length);
        return bytes + (mesh.materialIds() == null ? 0 : align(4L * mesh.materialIds().length));
    }

    private static void putFloats(ByteBuffer out, float[] values) {
        if (values != null) {
            out.asFloatBuffer().put(values);
            out.position(out.position() + 4 * values.length);
            pad(out);
        }
    }

    private static void putInts(ByteBuffer out, int[] values) {
        if (values != null) {
            out.asIntBuffer().put(values);
            out.position(out.position() + 4 * values.length);
            pad(out);
        }
    }

    private static float[] getFloats(ByteBuffer in, int n) {
        float[] values = new float[n];
        in.asFloatBuffer().get(values);
        in.position(align(in.position() + 4 * n));
        return values;
    }

    private static int[] getInts(ByteBuffer in, int n) {
        int[] values = new int[n];
        in.asIntBuffer().get(values);
        in.position(align(in.position() + 4 * n));
        return values;
    }

    private static void pad(ByteBuffer out) {
        out.position(align(out.position()));
    }

    private static int align(int position) {
        return (position + 7) & ~7;
    }

    private static long align(long bytes) {
        return (bytes + 7) & ~7L;
    }

    private static void readFully(FileChannel channel, ByteBuffer buffer) throws IOException {
        while (buffer.hasRemaining()) {
            if (channel.read(buffer) < 0) {
                throw new IOException("it ends early (it shrank while it was read)");
            }
        }
        buffer.flip();
    }

    /** The content stamp of a file now, recorded under {@code path}. */
    static Stamp stamp(Path file, String path) throws IOException {
        long size = Files.size(file);
        CRC32C crcC = new CRC32C();
        CRC32 crc = new CRC32();
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            // a mapping holds at most 2 GiB: larger files go in pieces
            for (long at = 0; at < size; at += 1L << 30) {
                ByteBuffer piece = channel.map(FileChannel.MapMode.READ_ONLY, at, Math.min(1L << 30, size - at));
                crcC.update(piece.duplicate());
                crc.update(piece);
            }
        }
        return new Stamp(path, size, crcC.getValue() << 32 | crc.getValue());
    }
}

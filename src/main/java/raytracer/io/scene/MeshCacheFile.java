package raytracer.io.scene;

import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.MappedByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.zip.CRC32C;
import raytracer.accel.BvhFile;
import raytracer.accel.FlatBVH;
import raytracer.image.AtomicFile;
import raytracer.io.obj.ObjMaterial;
import raytracer.math.BBox;
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
 * The length catches a truncated file at once from the header; the checksum catches any other
 * damage when the arrays are read.
 */
final class MeshCacheFile {
    /**
     * The layout above and what the OBJ reader and {@link MeshReader} make of a file: add 1 when
     * either changes, so that files written before are rebuilt rather than trusted.
     */
    static final int VERSION = 3;
    private static final long MAGIC = 0x0000_4853_454d_5452L; // "RTMESH\0\0" little-endian
    private static final int PREAMBLE = 8 + 4 + 4 + 8 + 4;

    private MeshCacheFile() {
    }

    /** The identity of a file a cached mesh was made from: where it was, its size, time and checksum. */
    record Stamp(String path, long size, long modified, int crc) {
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

    /** A mesh and its tree as read back. */
    record Contents(Mesh mesh, FlatBVH bvh) {
    }

    /** Writes the file atomically (temporary file and rename). */
    static void write(Path file, Header header, Mesh mesh, FlatBVH bvh) throws IOException {
        byte[] head = MeshCacheHeader.encode(header);
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
     * The header of a cache file, read without its arrays; an IOException says why the file is
     * not one this program can use (not a cache file, another version, truncated, unreadable).
     */
    static Header readHeader(Path file) throws IOException {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            ByteBuffer preamble = ByteBuffer.allocate(PREAMBLE).order(ByteOrder.LITTLE_ENDIAN);
            readFully(channel, preamble);
            int headerLength = checkPreamble(preamble, channel.size());
            ByteBuffer head = ByteBuffer.allocate(headerLength);
            readFully(channel, head);
            return MeshCacheHeader.decode(head.array());
        }
    }

    /** The whole file: checksum first, then the arrays. */
    static Contents read(Path file) throws IOException {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = channel.size();
            if (size < PREAMBLE + 4 || size > Integer.MAX_VALUE) {
                throw new IOException("it has " + size + " bytes");
            }
            MappedByteBuffer map = channel.map(FileChannel.MapMode.READ_ONLY, 0, size);
            map.order(ByteOrder.LITTLE_ENDIAN);
            CRC32C crc = new CRC32C();
            crc.update(map.duplicate().limit((int) size - 4));
            if ((int) crc.getValue() != map.getInt((int) size - 4)) {
                throw new IOException("its checksum does not match its contents");
            }
            int headerLength = checkPreamble(map, size);
            byte[] head = new byte[headerLength];
            map.get(head);
            Header header = MeshCacheHeader.decode(head);
            if (24L * header.vertices() + 12L * header.triangles() > size) {
                throw new IOException("its header counts more vertices and triangles than it holds");
            }
            map.position(align(map.position()));
            double[] positions = new double[3 * header.vertices()];
            map.asDoubleBuffer().get(positions);
            map.position(map.position() + 8 * positions.length);
            float[] normals = header.normals() ? getFloats(map, 3 * header.vertices()) : null;
            float[] uvs = header.uvs() ? getFloats(map, 2 * header.vertices()) : null;
            int[] triangles = getInts(map, 3 * header.triangles());
            int[] ids = header.materialIds() ? getInts(map, header.triangles()) : null;
            FlatBVH bvh = BvhFile.read(map);
            return new Contents(new Mesh(positions, normals, uvs, triangles, ids), bvh);
        } catch (IllegalArgumentException | IndexOutOfBoundsException | BufferUnderflowException e) {
            throw new IOException("its contents are inconsistent (" + e.getMessage() + ")", e);
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
                throw new IOException("it ends early");
            }
        }
        buffer.flip();
    }

    /** The size, time and checksum of a file now. */
    static Stamp stamp(Path file) throws IOException {
        long size = Files.size(file);
        long modified = Files.getLastModifiedTime(file).to(TimeUnit.NANOSECONDS);
        CRC32C crc = new CRC32C();
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            // a mapping holds at most 2 GiB: larger files go in pieces
            for (long at = 0; at < size; at += 1L << 30) {
                crc.update(channel.map(FileChannel.MapMode.READ_ONLY, at, Math.min(1L << 30, size - at)));
            }
        }
        return new Stamp(file.toAbsolutePath().normalize().toString(), size, modified, (int) crc.getValue());
    }
}

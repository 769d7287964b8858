package raytracer.cache;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import raytracer.accel.BvhFile;
import raytracer.accel.FlatBVH;
import raytracer.image.AtomicFile;
import raytracer.shapes.mesh.Mesh;

/**
 * The mesh cache's file: a parsed mesh, renumbered in its BVH's leaf order, and the BVH, in bytes
 * that are copied into the arrays in bulk. Little-endian throughout:
 *
 * <pre>
 *   long magic "RTMESH", int {@link #VERSION}, int {@link BvhFile#VERSION}, long file length
 *   int header length, header ({@link MeshCacheHeader})
 *   double[3 v] positions, float[3 v] normals?, float[2 v] uvs?, int[3 t] triangles, int[t] material ids?
 *   the BVH ({@link BvhFile}, in the mesh's order: no leaf order), each array starting on a multiple of 8
 *   int CRC-32C of every byte before it
 * </pre>
 *
 * An entry is read whole, once, and nothing of it is used before its length, its checksum and the
 * consistency of every part with the others have been checked ({@link #read}).
 */
final class MeshCacheFile {
    /**
     * The layout above, how entries are named, and what the mesh readers make of a file: add 1
     * when any changes, so that files written before are rebuilt rather than trusted (6: named by
     * the CRC-32C and CRC-32 of their key instead of its SHA-256).
     */
    static final int VERSION = 6;
    private static final long MAGIC = 0x0000_4853_454d_5452L; // "RTMESH\0\0" little-endian
    /** The first bytes of every entry, by which the cache knows its own files among others in its folder. */
    static final byte[] MAGIC_BYTES = {'R', 'T', 'M', 'E', 'S', 'H', 0, 0};
    private static final int PREAMBLE = 8 + 4 + 4 + 8 + 4;

    private MeshCacheFile() {
    }

    /** Bytes of an entry of {@code mesh} and {@code bvh}, but for its header (a few hundred bytes more). */
    static long size(Mesh mesh, FlatBVH bvh) {
        return align(PREAMBLE) + arrays(mesh) + align(BvhFile.size(bvh)) + 4;
    }

    /**
     * What writes the file, streamed through a small buffer (the caller writes it through a
     * temporary file and a rename); texture paths are written relative to {@code folder}, the OBJ
     * file's.
     */
    static AtomicFile.Body body(MeshCacheHeader header, Mesh mesh, FlatBVH bvh, Path folder) throws IOException {
        byte[] head = header.encode(folder);
        long length = align(PREAMBLE + head.length) + arrays(mesh) + align(BvhFile.size(bvh)) + 4;
        return stream -> {
            ChecksummedOutput out = new ChecksummedOutput(stream);
            try {
                out.putLong(MAGIC);
                out.putInt(VERSION);
                out.putInt(BvhFile.VERSION);
                out.putLong(length);
                out.putInt(head.length);
                out.putBytes(head);
                out.pad();
                out.putDoubles(mesh.positions());
                putFloats(out, mesh.normals());
                putFloats(out, mesh.uvs());
                putInts(out, mesh.triangles());
                putInts(out, mesh.materialIds());
                BvhFile.write(bvh, out);
                out.pad();
                if (out.position() != length - 4) {
                    throw new IllegalStateException("wrote " + out.position() + " bytes where " + (length - 4) + " were due");
                }
                out.finish();
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        };
    }

    /**
     * The whole file, read once (one open, one pass: an entry replaced meanwhile cannot mix two
     * versions) straight into the mesh's and the tree's arrays, and checked before any of it is
     * used: its length first, its checksum over every byte, then the header's counts against the
     * arrays, the bounds against the vertices, every value finite, every index and material id in
     * range, the tree's links. The arrays are filled as the bytes arrive (the header's counts are
     * read first, provisionally, to size them); if the header cannot be read or its counts do not
     * fit, the rest is only counted into the checksum. An IOException says why the file is not one
     * this program can use.
     */
    static MeshCacheEntry read(Path file, Path folder) throws IOException {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = channel.size();
            if (size < PREAMBLE + 4) {
                throw new IOException("it has " + size + " bytes");
            }
            ChecksummedInput in = new ChecksummedInput(channel, size - 4);
            MeshCacheParts parts = null;
            Exception failed = null;
            try {
                // the preamble only chooses the message of a file refused anyway: another format, cut short
                int headerLength = checkPreamble(in, size);
                byte[] head = new byte[headerLength];
                in.getBytes(head);
                in.align();
                try {
                    parts = new MeshCacheParts(MeshCacheHeader.decode(head, folder));
                    parts.read(in, size);
                } catch (IOException | RuntimeException e) {
                    failed = e;
                }
                in.skip(in.remaining()); // the checksum covers every byte
                ByteBuffer stored = ByteBuffer.allocate(4).order(ByteOrder.LITTLE_ENDIAN);
                while (stored.hasRemaining() && channel.read(stored, size - 4 + stored.position()) > 0) {
                    // the last four bytes
                }
                if (stored.hasRemaining() || in.checksum() != stored.getInt(0)) {
                    throw new IOException("its checksum does not match its contents");
                }
                if (channel.size() != size) {
                    throw new IOException("it " + (channel.size() > size ? "grew" : "shrank") + " while it was read");
                }
            } catch (UncheckedIOException e) {
                throw e.getCause();
            } catch (BufferUnderflowException e) {
                throw new IOException("it ends early", e);
            }
            if (failed instanceof IOException e) {
                throw e;
            }
            if (failed != null) {
                throw new IOException("its contents are inconsistent (" + failed.getMessage() + ")", failed);
            }
            try {
                return parts.check();
            } catch (IllegalArgumentException | IndexOutOfBoundsException e) {
                throw new IOException("its contents are inconsistent (" + e.getMessage() + ")", e);
            }
        }
    }

    /**
     * An entry of another format or BVH version: what every entry becomes when the program is
     * upgraded, so it is replaced without a warning (a damaged entry is warned of).
     */
    static final class OtherVersion extends IOException {
        OtherVersion(String message) {
            super(message);
        }
    }

    /** Checks magic, versions and length; returns the header's length, with the input just past the preamble. */
    private static int checkPreamble(ChecksummedInput in, long fileSize) throws IOException {
        if (in.getLong() != MAGIC) {
            throw new IOException("it is not a mesh cache file");
        }
        int version = in.getInt();
        int bvhVersion = in.getInt();
        if (version != VERSION || bvhVersion != BvhFile.VERSION) {
            throw new OtherVersion("it was written by another version (format " + version + ", BVH " + bvhVersion
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

    private static void putFloats(ChecksummedOutput out, float[] values) {
        if (values != null) {
            out.putFloats(values);
            out.pad();
        }
    }

    private static void putInts(ChecksummedOutput out, int[] values) {
        if (values != null) {
            out.putInts(values);
            out.pad();
        }
    }

    private static int align(int position) {
        return (position + 7) & ~7;
    }

    private static long align(long bytes) {
        return (bytes + 7) & ~7L;
    }
}

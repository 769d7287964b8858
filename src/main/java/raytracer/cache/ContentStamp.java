package raytracer.cache;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * The identity of a file's content: its size and the {@link Checksum} of all its bytes. Two
 * different files of one size pass as one with odds of 2^-64. {@code path} names the file for
 * whoever keeps the stamp (relative to a folder of theirs, or empty).
 */
public record ContentStamp(String path, long size, long digest) {

    /** The stamp of {@code file}'s bytes, recorded under the name {@code path}. */
    public static ContentStamp of(Path file, String path) throws IOException {
        long size = Files.size(file);
        Checksum sum = new Checksum();
        // read through one small buffer, not mapped: a mapping's pages count in the process's RSS
        // until the mapping is collected, and a mesh's source is stamped before its entry is read
        // (a 141 MB OBJ read from the cache took 347 MiB of RSS mapped, its 66 MB PLY twin 270)
        ByteBuffer buffer = ByteBuffer.allocateDirect(1 << 20);
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            // the first size bytes, as Files.size saw them, should the file grow meanwhile
            for (long left = size; left > 0 && channel.read(buffer) >= 0; ) {
                buffer.flip();
                buffer.limit((int) Math.min(buffer.limit(), left));
                left -= buffer.remaining();
                sum.update(buffer);
                buffer.clear();
            }
        }
        return new ContentStamp(path, size, sum.value());
    }

    /** {@code size digest}, the digest in hex: one line of a key. */
    public String identity() {
        return size + " " + Long.toHexString(digest);
    }
}

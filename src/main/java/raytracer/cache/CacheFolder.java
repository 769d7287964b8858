package raytracer.cache;

import java.io.IOException;
import java.io.InputStream;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.locks.ReentrantLock;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import raytracer.image.AtomicFile;
import raytracer.image.FileKind;

/**
 * A folder of cache entries, kept under a cap by deleting the least recently used ones. The folder
 * may be one the user also keeps files in ({@code --cache-dir models}), so the cache deletes only
 * what it can prove it wrote: a regular file (not a link) named as its entries are and starting
 * with its format's magic bytes, or a temporary file of such an entry, named as
 * {@link AtomicFile} names them, that a killed writer left ({@link #STALE_PARTIAL} old, and empty
 * or starting with the magic). Anything else in the folder is never opened for writing, moved or
 * deleted.
 *
 * <p>Writers in several processes (two renders, a Spark job's executors) and several threads may
 * store entries at once. Each writes its entry and trims the folder while holding the folder's
 * lock, so the set of entries changes in one place at a time and the cap holds whenever no writer
 * is inside: a directory listing taken while another writer renames its entry into place may or
 * may not show it (POSIX leaves it open), which had let two writers each see the other's entry
 * missing and both leave the folder over its cap.
 */
public final class CacheFolder {
    /** A temporary file this old is a killed writer's: writing an entry takes well under a second. */
    public static final Duration STALE_PARTIAL = Duration.ofHours(1);
    /** The lock file, an empty file of this program's own in the folder (never deleted: deleting a lock file races). */
    static final String LOCK_NAME = ".raytracer-cache.lock";
    /** A file lock is held by a process, not a thread: threads of one JVM take this lock of the folder first. */
    private static final ConcurrentHashMap<Path, ReentrantLock> THREAD_LOCKS = new ConcurrentHashMap<>();

    private final Path dir;
    private final Pattern entryName;
    private final Pattern partialName;
    private final byte[] magic;

    /**
     * The folder {@code dir} whose entries are named by {@code entryName} (a regular expression of
     * the whole name) and begin with {@code magic}.
     */
    public CacheFolder(Path dir, String entryName, byte[] magic) {
        this.dir = dir;
        this.entryName = Pattern.compile(entryName);
        // AtomicFile's temporary name: a dot, the target's name, a dot, a random base-36 number, ".partial"
        this.partialName = Pattern.compile("\\.(?:" + entryName + ")\\.[0-9a-z]{1,13}\\.partial");
        this.magic = magic.clone();
    }

    public Path dir() {
        return dir;
    }

    /** Makes the folder, saying so when something else is at its name. */
    public void create() throws IOException {
        FileKind kind = FileKind.of(dir);
        if (kind != FileKind.DIRECTORY && kind != FileKind.MISSING) {
            throw new IOException(dir + " is " + kind.words() + ", not a folder");
        }
        Files.createDirectories(dir);
    }

    /** True when {@code file} is an entry of this cache: a regular file named as entries are, starting with the magic bytes. */
    public boolean owns(Path file) {
        return entryName.matcher(file.getFileName().toString()).matches() && startsWithMagic(file, false);
    }

    /** True when {@code file} is the temporary file of an entry of this cache (empty when its writer was killed before its first write). */
    boolean ownsPartial(Path file) {
        return partialName.matcher(file.getFileName().toString()).matches() && startsWithMagic(file, true);
    }

    private boolean startsWithMagic(Path file, boolean emptyToo) {
        if (FileKind.ofLink(file) != FileKind.REGULAR) {
            return false;
        }
        try (InputStream in = Files.newInputStream(file, LinkOption.NOFOLLOW_LINKS)) {
            byte[] head = in.readNBytes(magic.length);
            return Arrays.equals(head, magic) || emptyToo && head.length == 0;
        } catch (IOException e) {
            return false;
        }
    }

    /** What {@link #store} did besides writing: how many entries it evicted, or why it could not keep the cap. */
    public record Trimmed(int evicted, IOException failure) {
    }

    /**
     * Writes {@code entry} (a name in this folder that {@link #owns} would accept) through a
     * temporary file and a rename, then deletes stale temporary files of this cache and the least
     * recently used entries but {@code entry} until all fit in {@code maxBytes}; all of it under
     * the folder's lock. A failure to write is the IOException; a failure to trim is reported in
     * the result, the entry being written.
     */
    public Trimmed store(Path entry, AtomicFile.Body body, long maxBytes) throws IOException {
        create();
        ReentrantLock threads = THREAD_LOCKS.computeIfAbsent(dir.toAbsolutePath().normalize(), d -> new ReentrantLock());
        threads.lock();
        try (FileChannel channel = FileChannel.open(dir.resolve(LOCK_NAME), StandardOpenOption.CREATE, StandardOpenOption.WRITE)) {
            // released when the channel closes, and by the system when the process dies
            channel.lock();
            AtomicFile.replace(entry, body);
            try {
                removeStalePartials();
                return new Trimmed(evict(maxBytes, entry), null);
            } catch (IOException e) {
                return new Trimmed(0, e);
            }
        } finally {
            threads.unlock();
        }
    }

    /** Marks an entry used now: the least recently used order is that of modification times. */
    public static void markUsed(Path entry) {
        try {
            Files.setLastModifiedTime(entry, FileTime.from(Instant.now()));
        } catch (IOException e) {
            // a cache in a read-only folder still serves; its entries are only evicted sooner
        }
    }

    /** The entries of this cache, with their sizes and last use. */
    List<Entry> entries() throws IOException {
        List<Entry> entries = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                if (owns(file)) {
                    try {
                        entries.add(new Entry(file, Files.size(file), Files.getLastModifiedTime(file, LinkOption.NOFOLLOW_LINKS)));
                    } catch (IOException gone) {
                        // deleted meanwhile, by hand
                    }
                }
            }
        }
        return entries;
    }

    record Entry(Path file, long size, FileTime used) {
    }

    /** Deletes the least recently used entries but {@code kept} until all fit under {@code maxBytes}; returns how many. */
    private int evict(long maxBytes, Path kept) throws IOException {
        List<Entry> entries = entries();
        long total = entries.stream().mapToLong(Entry::size).sum();
        entries.sort(Comparator.comparing(Entry::used));
        int evicted = 0;
        for (Entry e : entries) {
            if (total <= maxBytes) {
                break;
            }
            if (!e.file().equals(kept)) {
                Files.deleteIfExists(e.file());
                total -= e.size();
                evicted++;
            }
        }
        return evicted;
    }

    /** Deletes the temporary files of this cache's writers killed before they finished. */
    private void removeStalePartials() throws IOException {
        Instant before = Instant.now().minus(STALE_PARTIAL);
        try (Stream<Path> files = Files.list(dir)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                try {
                    if (ownsPartial(file) && Files.getLastModifiedTime(file, LinkOption.NOFOLLOW_LINKS).toInstant().isBefore(before)) {
                        Files.deleteIfExists(file);
                    }
                } catch (IOException gone) {
                    // renamed into place or deleted meanwhile
                }
            }
        }
    }
}

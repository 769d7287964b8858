package raytracer.cache;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.channels.FileChannel;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a cache may delete in its folder, and writers taking turns in it. */
class CacheFolderTest {
    private static final byte[] MAGIC = "TESTMAGC".getBytes(StandardCharsets.US_ASCII);
    private static final String ENTRY = "[a-z]{1,8}-[0-9a-f]{4}\\.entry";

    @TempDir
    Path dir;

    private static byte[] entry(int size) {
        byte[] bytes = new byte[size];
        System.arraycopy(MAGIC, 0, bytes, 0, MAGIC.length);
        return bytes;
    }

    @Test
    void ownsOnlyFilesNamedAsItsEntriesThatStartWithItsMagic() throws Exception {
        CacheFolder folder = new CacheFolder(dir, ENTRY, MAGIC);
        Path own = Files.write(dir.resolve("rock-00ff.entry"), entry(64));
        Path renamed = Files.write(dir.resolve("rock.entry"), entry(64));
        Path foreign = Files.writeString(dir.resolve("tree-00ff.entry"), "an entry's name, the user's content");
        Path link = Files.createSymbolicLink(dir.resolve("bush-00ff.entry"), own);
        Path folderNamedAsEntry = Files.createDirectory(dir.resolve("moss-00ff.entry"));
        assertTrue(folder.owns(own));
        assertFalse(folder.owns(renamed), "not named as an entry");
        assertFalse(folder.owns(foreign), "not the format's magic");
        assertFalse(folder.owns(link), "a link, even to an entry");
        assertFalse(folder.owns(folderNamedAsEntry));

        Path partial = Files.write(dir.resolve(".rock-00ff.entry.k3x9.partial"), entry(10));
        Path killedEarly = Files.write(dir.resolve(".rock-00ff.entry.a1.partial"), new byte[0]);
        Path userPartial = Files.writeString(dir.resolve(".rock-00ff.entry.a2.partial"), "notes");
        Path otherPartial = Files.write(dir.resolve(".notes.txt.a3.partial"), entry(10));
        assertTrue(folder.ownsPartial(partial));
        assertTrue(folder.ownsPartial(killedEarly), "nothing written yet: nothing of anyone's to lose");
        assertFalse(folder.ownsPartial(userPartial));
        assertFalse(folder.ownsPartial(otherPartial), "the temporary file of something else");
        assertEquals(List.of(own), folder.entries().stream().map(CacheFolder.Entry::file).toList());
    }

    /**
     * A writer stores and trims while it holds the folder: the lock of this JVM's threads and the
     * file lock other processes take. A second writer waits until the first is done, so the second
     * one's listing has the first one's entry.
     */
    @Test
    void aWriterWaitsWhileAnotherIsInsideTheFolder() throws Exception {
        CacheFolder folder = new CacheFolder(dir, ENTRY, MAGIC);
        CountDownLatch inside = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread first = new Thread(() -> {
            try {
                folder.store(dir.resolve("one-0001.entry"), out -> {
                    out.write(entry(1000));
                    inside.countDown();
                    try {
                        release.await();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }, 1500);
            } catch (Throwable e) {
                failed.set(e);
            }
        });
        first.start();
        inside.await();
        // another process would block here: this one holds the file lock
        try (FileChannel channel = FileChannel.open(dir.resolve(CacheFolder.LOCK_NAME), StandardOpenOption.WRITE)) {
            assertThrows(OverlappingFileLockException.class, channel::tryLock);
        }
        AtomicReference<CacheFolder.Trimmed> secondTrimmed = new AtomicReference<>();
        Thread second = new Thread(() -> {
            try {
                secondTrimmed.set(folder.store(dir.resolve("two-0002.entry"), out -> out.write(entry(1000)), 1500));
            } catch (Throwable e) {
                failed.set(e);
            }
        });
        second.start();
        second.join(300);
        assertTrue(second.isAlive(), "the second writer must wait for the first");
        assertFalse(Files.exists(dir.resolve("two-0002.entry")));
        release.countDown();
        first.join();
        second.join();
        assertEquals(null, failed.get());
        assertEquals(1, secondTrimmed.get().evicted(), "the second writer saw the first one's entry and evicted it");
        assertEquals(List.of(dir.resolve("two-0002.entry")), folder.entries().stream().map(CacheFolder.Entry::file).toList());
    }
}

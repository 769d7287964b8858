package raytracer.image;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.HashSet;
import java.util.Set;

/**
 * The temporary files {@link AtomicFile} is writing, deleted by a shutdown hook when the program is
 * stopped mid-write (SIGINT, SIGTERM, {@code System.exit}), so no {@code .NAME.xxx.partial} is left
 * beside the image. The set is process-wide because the hook is: the one static mutable state here,
 * guarded by the class lock, which also orders creation against the hook (a file is either created
 * before the hook runs, and then deleted by it, or refused).
 */
final class PartialFiles {
    private static final Set<Path> WRITING = new HashSet<>();
    private static boolean hookAdded;
    private static boolean stopping;

    private PartialFiles() {
    }

    /** Creates {@code temp} (failing if it exists) and remembers it until {@link #done}. */
    static synchronized OutputStream create(Path temp) throws IOException {
        if (stopping) {
            throw new IOException("the program is stopping");
        }
        if (!hookAdded) {
            Runtime.getRuntime().addShutdownHook(new Thread(PartialFiles::deleteAll, "delete partial files"));
            hookAdded = true;
        }
        OutputStream out = Files.newOutputStream(temp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        WRITING.add(temp);
        return out;
    }

    /** The file was renamed into place or deleted: nothing to clean up. */
    static synchronized void done(Path temp) {
        WRITING.remove(temp);
    }

    private static synchronized void deleteAll() {
        stopping = true;
        for (Path temp : WRITING) {
            try {
                Files.deleteIfExists(temp);
            } catch (IOException e) {
                // the process is ending; nothing better can be done with it
            }
        }
        WRITING.clear();
    }
}

package raytracer.image;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Writes a file through a temporary sibling and a rename, so readers see either the old file or the
 * complete new one, never a half-written one. If the program is stopped mid-write,
 * {@link PartialFiles} deletes the temporary file; one that a killed program left,
 * {@link #removeLeftovers} deletes when the file is written again.
 *
 * <p>Two kinds of file are written so. A file the user named ({@link #write}) is never destroyed:
 * a symbolic link is written through to its target (one to nothing is refused), a FIFO or a
 * character device ({@code /dev/null}, a terminal) is written into as it is, anything else that is
 * not a regular file is refused, and the result has the permissions of the file it replaces, or
 * the umask's ({@code Files.createTempFile} would make it owner-only). A file of this program's own,
 * such as a cache entry ({@link #replace}), replaces whatever is at its name, link or not, and
 * always has the umask's permissions.
 */
public final class AtomicFile {

    /** The body that writes the content. */
    @FunctionalInterface
    public interface Body {
        void writeTo(OutputStream out) throws IOException;
    }

    private AtomicFile() {
    }

    /** Writes a file the user named, as the class comment says: never replacing a link, FIFO or device. */
    public static void write(Path target, Body body) throws IOException {
        Path file = destination(target);
        FileKind kind = FileKind.of(file);
        if (kind.writtenInPlace()) {
            // no temporary file: a rename would put a regular file in the FIFO's or device's place
            try (OutputStream out = Files.newOutputStream(file, StandardOpenOption.WRITE)) {
                body.writeTo(out);
            } catch (IOException e) {
                throw failure(target, e);
            }
            return;
        }
        if (kind != FileKind.REGULAR && kind != FileKind.MISSING) {
            throw new IOException("cannot write " + target + ": it is " + kind.words() + ", not a regular file");
        }
        atomically(file, body, true);
    }

    /**
     * The file that writing {@code target} writes: itself, or the end of the chain of symbolic links
     * it starts (which may not exist yet: writing creates it). More than {@value #MOST_LINKS} links
     * in a row (a loop) is an IOException.
     */
    public static Path destination(Path target) throws IOException {
        Path file = target.toAbsolutePath();
        for (int hops = 0; FileKind.ofLink(file) == FileKind.SYMBOLIC_LINK; hops++) {
            if (hops == MOST_LINKS) {
                throw new IOException("cannot write " + target + ": too many levels of symbolic links (a loop?)");
            }
            file = file.getParent().resolve(Files.readSymbolicLink(file)).normalize();
        }
        return file;
    }

    /**
     * The longest name (in UTF-8 bytes) that can be written so: the temporary file's name is the
     * target's with a dot before it and at most 22 characters after it, and a folder entry holds
     * 255 bytes (NAME_MAX of Linux's file systems).
     */
    public static final int MAX_NAME_BYTES = 255 - 1 - 1 - 13 - ".partial".length();

    /** Linux's limit of links followed in one path (MAXSYMLINKS). */
    static final int MOST_LINKS = 40;

    /**
     * Writes a file of this program's own (a cache entry): whatever is at {@code target}, a link or
     * anything else, is replaced by a new regular file with the umask's permissions. Copying the
     * replaced file's would keep a mode-000 entry unreadable for ever, or make one that replaced a
     * link to a world-writable file world-writable.
     */
    public static void replace(Path target, Body body) throws IOException {
        atomically(target, body, false);
    }

    private static void atomically(Path target, Body body, boolean keepPermissions) throws IOException {
        try {
            writeThroughTemp(target, body, keepPermissions);
        } catch (IOException e) {
            throw failure(target, e);
        }
    }

    /** A write's failure as one line that names the file the user gave. */
    private static IOException failure(Path target, IOException e) {
        if (e instanceof FileSystemException fs) {
            // the bare exception names only the temporary file; say which file and why
            String reason = e instanceof NoSuchFileException ? "no such file or directory"
                            : e instanceof AccessDeniedException ? "permission denied"
                            : fs.getReason() != null ? fs.getReason() : e.getClass().getSimpleName();
            return new IOException("cannot write " + target + ": " + reason, e);
        }
        // the body's own failure, such as an encoder's message around the cause "File too large"
        String reason = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
        Throwable cause = e.getCause();
        if (cause != null && cause.getMessage() != null && !reason.contains(cause.getMessage())) {
            reason += " (" + cause.getMessage() + ")";
        }
        return new IOException("cannot write " + target + ": " + reason, e);
    }

    private static void writeThroughTemp(Path target, Body body, boolean keepPermissions) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path dir = absolute.getParent();
        Path temp = null;
        try {
            OutputStream stream = null;
            while (stream == null) {
                temp = dir.resolve(temporaryName(absolute.getFileName().toString(), ThreadLocalRandom.current().nextLong()));
                try {
                    stream = PartialFiles.create(temp);
                } catch (FileAlreadyExistsException taken) {
                    temp = null;
                }
            }
            try (OutputStream out = stream) {
                body.writeTo(out);
            }
            if (keepPermissions) {
                keepPermissionsOf(absolute, temp);
            }
            try {
                Files.move(temp, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, absolute, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            if (temp != null) {
                Files.deleteIfExists(temp);
                PartialFiles.done(temp);
            }
        }
    }

    /** {@link #temporaryName}'s names: the file's name, and at most 13 base-36 digits (an unsigned long's). */
    private static final Pattern TEMPORARY = Pattern.compile("\\.(.+)\\.[0-9a-z]{1,13}\\.partial");

    /** The name of a temporary file of a write of the file {@code name}: {@code .NAME.<random in base 36>.partial}. */
    private static String temporaryName(String name, long random) {
        return "." + name + "." + Long.toUnsignedString(random, 36) + ".partial";
    }

    /**
     * Deletes the temporary files that writes of {@code targets} left when the program was killed
     * mid-write (SIGKILL, a power cut: no shutdown hook ran, see {@link PartialFiles}): the regular
     * files beside each file written (the end of its links) whose names are {@link #temporaryName}'s
     * for it, and nothing else. A write of one of them running in another process at that moment
     * would lose its temporary file and fail: call it for files about to be written by this program
     * alone. Each folder is listed once, however many targets it holds. Returns the files deleted.
     */
    public static List<Path> removeLeftovers(Collection<Path> targets) throws IOException {
        Map<Path, Set<String>> names = new LinkedHashMap<>();
        for (Path target : targets) {
            Path file = destination(target);
            names.computeIfAbsent(file.getParent(), d -> new HashSet<>()).add(file.getFileName().toString());
        }
        List<Path> removed = new ArrayList<>();
        for (Map.Entry<Path, Set<String>> folder : names.entrySet()) {
            if (!Files.isDirectory(folder.getKey())) {
                continue;
            }
            try (DirectoryStream<Path> entries = Files.newDirectoryStream(folder.getKey())) {
                for (Path entry : entries) {
                    Matcher m = TEMPORARY.matcher(entry.getFileName().toString());
                    if (m.matches() && folder.getValue().contains(m.group(1)) && Files.isRegularFile(entry, LinkOption.NOFOLLOW_LINKS)
                        && Files.deleteIfExists(entry)) {
                        removed.add(entry);
                    }
                }
            }
        }
        return removed;
    }

    private static void keepPermissionsOf(Path replaced, Path temp) throws IOException {
        PosixFileAttributeView view = Files.getFileAttributeView(temp, PosixFileAttributeView.class);
        if (view != null && Files.exists(replaced)) {
            view.setPermissions(Files.getPosixFilePermissions(replaced));
        }
    }
}

package raytracer.image;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes a file through a temporary sibling and a rename, so readers see either the old file or the
 * complete new one, never a half-written one. The result has the permissions a plainly created file
 * would have (the umask's), or the replaced file's: {@code Files.createTempFile} would make it
 * owner-only. If the program is stopped mid-write, {@link PartialFiles} deletes the temporary file.
 */
public final class AtomicFile {

    /** The body that writes the content. */
    @FunctionalInterface
    public interface Body {
        void writeTo(OutputStream out) throws IOException;
    }

    private AtomicFile() {
    }

    public static void write(Path target, Body body) throws IOException {
        try {
            writeThroughTemp(target, body);
        } catch (FileSystemException e) {
            // the bare exception names only the temporary file; say which file and why
            String reason = e instanceof NoSuchFileException ? "no such file or directory"
                            : e instanceof AccessDeniedException ? "permission denied"
                            : e.getReason() != null ? e.getReason() : e.getClass().getSimpleName();
            throw new IOException("cannot write " + target + ": " + reason, e);
        } catch (IOException e) {
            // the body's own failure, such as an encoder's message around the cause "File too large"
            String reason = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
            Throwable cause = e.getCause();
            if (cause != null && cause.getMessage() != null && !reason.contains(cause.getMessage())) {
                reason += " (" + cause.getMessage() + ")";
            }
            throw new IOException("cannot write " + target + ": " + reason, e);
        }
    }

    private static void writeThroughTemp(Path target, Body body) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path dir = absolute.getParent();
        Path temp = null;
        try {
            OutputStream stream = null;
            while (stream == null) {
                temp = dir.resolve("." + absolute.getFileName() + "."
                        + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + ".partial");
                try {
                    stream = PartialFiles.create(temp);
                } catch (FileAlreadyExistsException taken) {
                    temp = null;
                }
            }
            try (OutputStream out = stream) {
                body.writeTo(out);
            }
            keepPermissionsOf(absolute, temp);
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

    private static void keepPermissionsOf(Path replaced, Path temp) throws IOException {
        PosixFileAttributeView view = Files.getFileAttributeView(temp, PosixFileAttributeView.class);
        if (view != null && Files.exists(replaced)) {
            view.setPermissions(Files.getPosixFilePermissions(replaced));
        }
    }
}

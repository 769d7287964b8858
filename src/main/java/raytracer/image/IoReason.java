package raytracer.image;

import java.io.EOFException;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/**
 * Why an I/O operation failed, in words: Java's file exceptions often carry only the path as
 * their message ("(/home/u/.cache)" says nothing) or none at all ("(null)"); this gives the reason
 * the operating system gave, or what the exception's kind means.
 */
public final class IoReason {
    private IoReason() {
    }

    public static String of(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file or directory" + other(e);
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied" + other(e);
        }
        if (e instanceof FileAlreadyExistsException f) {
            return f.getFile() + " is in the way (it exists and is not a folder)";
        }
        if (e instanceof NotDirectoryException f) {
            return f.getFile() + " is not a folder";
        }
        if (e instanceof FileSystemException f) {
            String reason = f.getReason();
            if (reason != null && !reason.isBlank()) {
                // the operating system's words, as a clause: "Too many levels of symbolic links" -> "too many ..."
                return Character.toLowerCase(reason.charAt(0)) + reason.substring(1) + other(e);
            }
            return e.getClass().getSimpleName() + other(e);
        }
        if (e instanceof EOFException && (e.getMessage() == null || e.getMessage().isBlank())) {
            return "it ends early";
        }
        String message = e.getMessage();
        return message == null || message.isBlank() ? e.getClass().getSimpleName() : message;
    }

    /** The file the failure was about, in parentheses, when the exception names one. */
    private static String other(IOException e) {
        return e instanceof FileSystemException f && f.getFile() != null ? " (" + f.getFile() + ")" : "";
    }
}

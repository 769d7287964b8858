package raytracer.image;

import java.io.IOException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * What a path names, from the file type bits of its mode (POSIX {@code st_mode & S_IFMT}): Java's
 * own attributes put FIFOs, devices and sockets together as "other", but an output may be written
 * into a FIFO or a character device and never into a block device, and an input must be a regular
 * file before a reader blocks on a FIFO or reads {@code /dev/zero} for ever.
 */
public enum FileKind {
    MISSING("missing"),
    REGULAR("a regular file"),
    DIRECTORY("a directory"),
    SYMBOLIC_LINK("a symbolic link"),
    FIFO("a FIFO (named pipe)"),
    CHARACTER_DEVICE("a character device"),
    BLOCK_DEVICE("a block device"),
    SOCKET("a socket"),
    /** Symbolic links that lead back to themselves: nothing can be read or written through them. */
    LINK_LOOP("a loop of symbolic links"),
    OTHER("not a file this program knows");

    private final String words;

    FileKind(String words) {
        this.words = words;
    }

    /** "a FIFO (named pipe)", for messages. */
    public String words() {
        return words;
    }

    /** What {@code path} names, following symbolic links (a link to nothing is {@link #MISSING}). */
    public static FileKind of(Path path) {
        return kind(path);
    }

    /** What {@code path} itself is: a symbolic link is {@link #SYMBOLIC_LINK}, not what it points to. */
    public static FileKind ofLink(Path path) {
        return kind(path, LinkOption.NOFOLLOW_LINKS);
    }

    private static FileKind kind(Path path, LinkOption... options) {
        int mode;
        try {
            mode = (Integer) Files.getAttribute(path, "unix:mode", options);
        } catch (NoSuchFileException e) {
            return MISSING;
        } catch (FileSystemException e) {
            // ELOOP: "Too many levels of symbolic links"
            if (e.getReason() != null && e.getReason().contains("symbolic links")) {
                return LINK_LOOP;
            }
            // a path through a regular file (ENOTDIR), too long, or through a folder that cannot be searched: nothing is there to read
            return MISSING;
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            // no unix view (another file system): what the portable attributes can tell
            return Files.isRegularFile(path, options) ? REGULAR : Files.isDirectory(path, options) ? DIRECTORY
                : Files.isSymbolicLink(path) && options.length > 0 ? SYMBOLIC_LINK : Files.exists(path, options) ? OTHER : MISSING;
        }
        return switch (mode & 0170000) {
            case 0100000 -> REGULAR;
            case 0040000 -> DIRECTORY;
            case 0120000 -> SYMBOLIC_LINK;
            case 0010000 -> FIFO;
            case 0020000 -> CHARACTER_DEVICE;
            case 0060000 -> BLOCK_DEVICE;
            case 0140000 -> SOCKET;
            default -> OTHER;
        };
    }

    /**
     * True for what an output is written into as it is, never replaced: a FIFO (a reader waits on
     * it) or a character device such as {@code /dev/null} or a terminal.
     */
    public boolean writtenInPlace() {
        return this == FIFO || this == CHARACTER_DEVICE;
    }

    /**
     * Why an input file cannot be read, or null when it is a regular file or missing (its reader
     * says "no such file"): "not a regular file (it is a FIFO (named pipe))". A FIFO would block its
     * reader for ever, a device never end.
     */
    public static String notRegular(Path file) {
        FileKind kind = of(file);
        return kind == REGULAR || kind == MISSING ? null : "not a regular file (it is " + kind.words() + ")";
    }
}

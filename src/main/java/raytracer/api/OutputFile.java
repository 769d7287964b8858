package raytracer.api;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import raytracer.image.AtomicFile;
import raytracer.image.FileKind;
import raytracer.image.ImageWriters;

/**
 * Where an output goes: the image's default name, and whether a file can be written, known before
 * rendering. Nothing the user named is destroyed: an output that is one of the run's inputs is
 * refused, a symbolic link is written through to its target, a FIFO or character device is
 * written into ({@link raytracer.image.AtomicFile#write}). The Spark job checks its local outputs
 * here too.
 */
public final class OutputFile {
    private OutputFile() {
    }

    /** {@code <scene name>.png} beside the working directory, {@code default.png} for the embedded scene. */
    public static Path defaultFor(Path scene) {
        if (scene == null) {
            return Path.of("default.png");
        }
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return Path.of((dot > 0 ? name.substring(0, dot) : name) + ".png");
    }

    /** Why the image could not be written to {@code out}, or null if it can be. */
    public static String whyUnwritable(Path out) {
        return whyUnwritable(out, false);
    }

    /**
     * As {@link #whyUnwritable(Path)}; with {@code folderMayBeMade}, a missing folder is no reason
     * when it can be made: the nearest part of its path that exists is a folder one can write in.
     */
    public static String whyUnwritable(Path out, boolean folderMayBeMade) {
        String extensions = String.join(", ", ImageWriters.EXTENSIONS);
        if (Files.isDirectory(out)) {
            return "it is a directory; give a file name ending in one of " + extensions;
        }
        if (!ImageWriters.isSupported(out)) {
            return "unsupported extension (use one of " + extensions + ")";
        }
        return whyNotWritable(out, folderMayBeMade);
    }

    /** Why any file could not be written to {@code out} (whatever its name), or null if it can be. */
    public static String whyNotWritable(Path out) {
        return whyNotWritable(out, false);
    }

    private static String whyNotWritable(Path out, boolean folderMayBeMade) {
        Path file;
        try {
            file = AtomicFile.destination(out);
        } catch (IOException e) {
            return "too many levels of symbolic links (a loop?)";
        }
        Path name = file.getFileName();
        int bytes = name == null ? 0 : name.toString().getBytes(StandardCharsets.UTF_8).length;
        if (bytes > AtomicFile.MAX_NAME_BYTES) {
            return "the file name is " + bytes + " bytes long; at most " + AtomicFile.MAX_NAME_BYTES + " fit (a folder entry "
                   + "holds 255, and the temporary file written first adds " + (255 - AtomicFile.MAX_NAME_BYTES) + ")";
        }
        FileKind kind = FileKind.of(file);
        if (kind == FileKind.DIRECTORY) {
            return "it is a directory";
        }
        if (kind.writtenInPlace()) {
            return Files.isWritable(file) ? null : "it is " + kind.words() + " that is not writable";
        }
        if (kind != FileKind.REGULAR && kind != FileKind.MISSING) {
            return "it is " + kind.words() + ", not a regular file";
        }
        Path dir = file.toAbsolutePath().getParent();
        if (folderMayBeMade && dir != null && kind == FileKind.MISSING && !Files.isDirectory(dir)) {
            return whyNoFolder(dir);
        }
        if (dir == null || !Files.isDirectory(dir)) {
            return (file.equals(out.toAbsolutePath()) ? "" : "it is a symbolic link to " + file + ", and ")
                   + "directory " + dir + " does not exist";
        }
        if (!Files.isWritable(dir)) {
            return "directory " + dir + " is not writable";
        }
        if (Files.exists(file) && !Files.isWritable(file)) {
            return "it is read-only";
        }
        return null;
    }

    /**
     * Why folder {@code dir}, missing, cannot be made, or null: the nearest part of its path that
     * is there must be a folder (or a link to one) that one can write in.
     */
    private static String whyNoFolder(Path dir) {
        Path there = dir;
        while (there != null && FileKind.ofLink(there) == FileKind.MISSING) {
            there = there.getParent();
        }
        if (there == null) {
            return "no part of folder " + dir + " exists";
        }
        FileKind kind = FileKind.of(there);
        if (kind == FileKind.MISSING) {
            return "folder " + dir + " cannot be made: " + there + " is a symbolic link to nothing";
        }
        if (kind != FileKind.DIRECTORY) {
            return "folder " + dir + " cannot be made: " + there + " is " + kind.words() + ", not a folder";
        }
        return Files.isWritable(there) ? null : "folder " + dir + " cannot be made: folder " + there + " is not writable";
    }

    /**
     * Why {@code out} must not be written because the run reads it, or null: it is the scene, or
     * one of the files the scene read ({@code inputs}: meshes, material libraries, images), or
     * {@code otherInputs} (the reference). The same file under another name (a link) counts.
     */
    public static String whyInput(Path out, Path scene, Collection<Path> inputs, Path... otherInputs) {
        if (scene != null && same(out, scene)) {
            return "it is the scene";
        }
        for (Path other : otherInputs) {
            if (other != null && same(out, other)) {
                return "it is the reference";
            }
        }
        for (Path input : inputs) {
            if (same(out, input)) {
                return "it is one of the scene's inputs (" + input + ")";
            }
        }
        return null;
    }

    /** True when both name one file: the same path, or existing files that are one (links, hard links). */
    public static boolean same(Path a, Path b) {
        if (a.toAbsolutePath().normalize().equals(b.toAbsolutePath().normalize())) {
            return true;
        }
        try {
            return Files.exists(a) && Files.exists(b) && Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }
}

package raytracer.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import raytracer.image.ImageWriters;

/** Where the image goes: the default name, and whether the file can be written, known before rendering. */
final class OutputFile {
    private OutputFile() {
    }

    /** {@code <scene name>.png} beside the working directory, {@code default.png} for the embedded scene. */
    static Path defaultFor(Path scene) {
        if (scene == null) {
            return Path.of("default.png");
        }
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return Path.of((dot > 0 ? name.substring(0, dot) : name) + ".png");
    }

    /** Why the image could not be written to {@code out}, or null if it can be. */
    static String whyUnwritable(Path out) {
        String extensions = String.join(", ", ImageWriters.EXTENSIONS);
        if (Files.isDirectory(out)) {
            return "it is a directory; give a file name ending in one of " + extensions;
        }
        if (!ImageWriters.isSupported(out)) {
            return "unsupported extension (use one of " + extensions + ")";
        }
        Path dir = out.toAbsolutePath().getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            return "directory " + dir + " does not exist";
        }
        if (!Files.isWritable(dir)) {
            return "directory " + dir + " is not writable";
        }
        if (Files.exists(out) && !Files.isWritable(out)) {
            return "it is read-only";
        }
        return null;
    }
}

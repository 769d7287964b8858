package raytracer.spark;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.util.Collection;
import java.util.List;
import java.util.UUID;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FSDataOutputStream;
import org.apache.hadoop.fs.FileStatus;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.LocalFileSystem;
import org.apache.hadoop.fs.Path;
import raytracer.api.FrameFiles;
import raytracer.api.FrameRange;
import raytracer.api.OutputFile;
import raytracer.image.ImageWriters;

/**
 * Images on any Hadoop file system ({@code file:}, {@code hdfs:}, {@code s3a:}), written under
 * fixed names and atomically: to a temporary file beside the target, named after the run
 * ({@code .frame-0001.png.<run>-<random>.partial}), then renamed. A retried or speculative task
 * writes the same bytes to the same name, so whichever rename lands, the file is right; a task
 * killed while writing leaves only a temporary file, which the driver deletes at the end of the run
 * ({@link #removePartials}). Local files are written without Hadoop's checksum side files.
 */
final class Outputs {
    private Outputs() {
    }

    /** The file system of {@code path}; the local one without its checksum files. */
    static FileSystem fileSystem(Path path, Configuration conf) throws IOException {
        FileSystem fs = path.getFileSystem(conf);
        return fs instanceof LocalFileSystem local ? local.getRaw() : fs;
    }

    /** {@code name} made absolute on its file system (a relative name is the driver's working folder), as a URI string. */
    static String qualify(String name, Configuration conf) throws IOException {
        Path path = new Path(name);
        return fileSystem(path, conf).makeQualified(path).toString();
    }

    /** The bytes of a file, written by {@code body}. */
    interface Body {
        void write(OutputStream out) throws IOException;
    }

    /** Writes {@code target} atomically through a temporary file of run {@code runId}; returns the bytes written. */
    static long write(String target, String runId, Configuration conf, Body body) throws IOException {
        Path file = new Path(target);
        FileSystem fs = fileSystem(file, conf);
        Path partial = new Path(file.getParent(), "." + file.getName() + "." + runId + "-" + UUID.randomUUID() + ".partial");
        long size;
        try {
            try (FSDataOutputStream out = fs.create(partial, false)) {
                body.write(out);
                out.flush();
                size = out.getPos();
            }
            if (!fs.rename(partial, file)) {
                // a file system whose rename does not replace (HDFS): another attempt of this task wrote the same bytes first
                if (!fs.exists(file) || fs.getFileStatus(file).getLen() != size) {
                    throw new IOException("cannot rename " + partial + " to " + file);
                }
                fs.delete(partial, false);
            }
        } catch (IOException | RuntimeException e) {
            try {
                fs.delete(partial, false);
            } catch (IOException ignored) {
                // the driver removes what is left at the end of the run
            }
            throw e;
        }
        return size;
    }

    /** Leaves a temporary file of run {@code runId} beside {@code target}, as a writer killed mid-file does (a test's hook). */
    static void leavePartial(String target, String runId, Configuration conf) throws IOException {
        Path file = new Path(target);
        FileSystem fs = fileSystem(file, conf);
        try (FSDataOutputStream out = fs.create(new Path(file.getParent(), "." + file.getName() + "." + runId + "-hook.partial"), true)) {
            out.write(new byte[] {'P', 'N'});
        }
    }

    /** Deletes the temporary files of run {@code runId} in the folders of {@code targets}; returns how many. */
    static int removePartials(Collection<String> targets, String runId, Configuration conf) throws IOException {
        int removed = 0;
        for (String folder : targets.stream().map(t -> new Path(t).getParent().toString()).distinct().toList()) {
            Path dir = new Path(folder);
            FileSystem fs = fileSystem(dir, conf);
            if (!fs.exists(dir)) {
                continue;
            }
            for (FileStatus status : fs.listStatus(dir)) {
                String name = status.getPath().getName();
                if (name.startsWith(".") && name.endsWith(".partial") && name.contains("." + runId + "-")) {
                    removed += fs.delete(status.getPath(), false) ? 1 : 0;
                }
            }
        }
        return removed;
    }

    /** Makes the folder of {@code target}. */
    static void makeFolder(String target, Configuration conf) throws IOException {
        Path file = new Path(target);
        if (!fileSystem(file, conf).mkdirs(file.getParent())) {
            throw new IOException("cannot make the folder " + file.getParent());
        }
    }

    /** {@code <scene name>.png} (of the embedded scene, {@code default.png}), or of an animation {@code <scene name>-%04d.png}. */
    static String defaultFor(java.nio.file.Path scene, boolean animation) {
        String name = scene == null ? "default" : scene.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        return animation ? name.replace("%", "%%") + "-%04d.png" : name + ".png";
    }

    /**
     * Why the output {@code out} (a pattern with {@code range}) cannot be written, as a usage
     * error's message, or null: known before any work. A pattern must name the frames, the
     * extension be one render writes, and a local output follow render's rules: never the scene
     * ({@code scene}, null for the embedded one), and writable (its folder may be missing: it is
     * made); the files the scene reads are checked by the tasks.
     */
    static String whyNotWritable(String out, FrameRange range, java.nio.file.Path scene) {
        if (range != null && FrameFiles.whyNotPattern(out) != null) {
            return "-o " + out + " cannot name the frames: " + FrameFiles.whyNotPattern(out);
        }
        if (!ImageWriters.isSupported(range != null ? FrameFiles.format(out, 0) : out)) {
            return "cannot write " + out + ": unsupported extension (use one of " + String.join(", ", ImageWriters.EXTENSIONS) + ")";
        }
        java.nio.file.Path local = localFile(range != null ? FrameFiles.format(out, range.first()) : out);
        if (local == null) {
            return null;
        }
        java.nio.file.Path folder = local.toAbsolutePath().getParent();
        String why = OutputFile.whyInput(local, scene, List.of());
        if (why == null && folder != null && Files.isDirectory(folder)) {
            why = OutputFile.whyUnwritable(local);
        }
        return why == null ? null : "cannot write " + out + ": " + why;
    }

    /** The local file {@code target} names (a plain path or {@code file:}), or null on any other file system. */
    static java.nio.file.Path localFile(String target) {
        java.net.URI uri = new Path(target).toUri();
        return uri.getScheme() == null ? java.nio.file.Path.of(target)
            : "file".equals(uri.getScheme()) ? java.nio.file.Path.of(uri) : null;
    }

    /**
     * Why {@code target} must not be written because the frame read it (a texture, a mesh named as
     * the output: the rule of {@code render}, {@link OutputFile#whyInput}), or null.
     */
    static String whyInput(String target, java.util.Collection<java.nio.file.Path> inputs) {
        java.nio.file.Path local = localFile(target);
        String why = local == null ? null : OutputFile.whyInput(local, null, inputs);
        return why == null ? null : "cannot write " + target + ": " + why;
    }
}

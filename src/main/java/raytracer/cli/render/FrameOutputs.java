package raytracer.cli.render;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import raytracer.api.FrameFiles;
import raytracer.api.FrameRange;
import raytracer.api.OutputFile;
import raytracer.image.AtomicFile;
import raytracer.image.ImageCheck;
import raytracer.image.IoReason;

/**
 * The files of a --frames run, all checked before the first frame renders, so that a run is
 * refused before it makes or writes anything rather than after some frames: which frames to
 * write (with --resume, those whose file is not a whole image of the run's size), that each file
 * can be written, its folder made when missing (as the Spark job's file system makes it: a hundred
 * frames go to a folder of their own, and one command works on one machine and on a cluster), and,
 * once the first frame loaded names the scene's inputs, that none is an input. Only then does
 * {@link #prepare} make the folders and delete what a killed run left beside the files.
 */
final class FrameOutputs {
    private final CommandLine commandLine;
    private final String pattern;
    /** The frames to write, in order. */
    private final List<Integer> frames;
    /** Of the frames --resume found a file of, but not a whole image: the file, why, and that it is rendered again. */
    private final List<String> redone;

    private FrameOutputs(CommandLine commandLine, String pattern, List<Integer> frames, List<String> redone) {
        this.commandLine = commandLine;
        this.pattern = pattern;
        this.frames = frames;
        this.redone = redone;
    }

    /**
     * The frames of {@code range} to write to the files {@code pattern} names, each file known to
     * be writable (a usage error names the first that is not); with {@code resume}, without those
     * whose file is a whole image of {@code width} x {@code height}.
     */
    static FrameOutputs plan(CommandLine commandLine, String pattern, FrameRange range, boolean resume, int width, int height) {
        List<Integer> frames = new ArrayList<>();
        List<String> redone = new ArrayList<>();
        for (int frame = range.first(); frame <= range.last(); frame++) {
            Path out = FrameFiles.name(pattern, frame);
            // a FIFO or a device is written into, never kept: only a regular file can be a frame already done
            if (resume && Files.isRegularFile(out)) {
                String why = ImageCheck.whyNotWhole(out, width, height);
                if (why == null) {
                    continue;
                }
                redone.add(out + " " + why + "; rendered again");
            }
            String unwritable = OutputFile.whyUnwritable(out, true);
            if (unwritable != null) {
                throw new ParameterException(commandLine, "cannot write " + out + ": " + unwritable);
            }
            frames.add(frame);
        }
        return new FrameOutputs(commandLine, pattern, frames, redone);
    }

    /** The frames to write, in order: the range's, less those --resume keeps. */
    List<Integer> frames() {
        return frames;
    }

    /** The warnings of the frames --resume renders again: "FILE is damaged (...); rendered again". */
    List<String> redone() {
        return redone;
    }

    /**
     * Refuses the run, a usage error, when a file to write is the scene or one of the files it
     * reads ({@code inputs}, as the first frame loaded names them: every frame reads the same).
     */
    void checkNotInputs(Path scene, Collection<Path> inputs) {
        for (int frame : frames) {
            Path out = FrameFiles.name(pattern, frame);
            String input = OutputFile.whyInput(out, scene, inputs);
            if (input != null) {
                throw new ParameterException(commandLine, "cannot write " + out + ": " + input);
            }
        }
    }

    /**
     * Once the run is accepted: makes the missing folders of the files to write, and deletes the
     * temporary files that a run killed mid-write left beside them (of these files alone).
     */
    void prepare() throws IOException {
        Set<Path> folders = new LinkedHashSet<>();
        List<Path> files = new ArrayList<>();
        for (int frame : frames) {
            Path out = FrameFiles.name(pattern, frame);
            files.add(out);
            Path folder = out.toAbsolutePath().getParent();
            if (folder != null) {
                folders.add(folder);
            }
        }
        for (Path folder : folders) {
            if (!Files.isDirectory(folder)) {
                try {
                    Files.createDirectories(folder);
                } catch (IOException e) {
                    throw new IOException("cannot make folder " + folder + ": " + IoReason.of(e), e);
                }
            }
        }
        AtomicFile.removeLeftovers(files);
    }
}

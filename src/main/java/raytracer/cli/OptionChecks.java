package raytracer.cli;

import java.nio.file.Path;
import java.util.function.Supplier;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import raytracer.api.FrameFiles;
import raytracer.api.FrameRange;
import raytracer.api.OutputFile;
import raytracer.api.SceneOptions;
import raytracer.cli.render.RenderRequest;
import raytracer.cli.show.GraphicalDisplay;

/**
 * Checks render's own option values that picocli's types cannot (ranges, names, the output file)
 * and parses them, with the options it shares ({@link RenderOptions}, which checks those), into a
 * {@link RenderRequest}. Every bad value is a usage error, exit code 2, found before the scene is
 * loaded; the files of --frames are checked by {@code cli.render.FrameOutputs} once the scene is
 * read, before any is made.
 */
final class OptionChecks {
    private final CommandLine commandLine;

    OptionChecks(CommandLine commandLine) {
        this.commandLine = commandLine;
    }

    RenderRequest check(RenderCommand o) {
        int threads = o.options.threads();
        requireAtLeast("--repeat", o.repeat, 1);
        boolean costView = usage(() -> parseView(o.view));
        SceneOptions options = o.options.sceneOptions(o.image, costView);
        FrameRange frames = o.frames == null ? null : usage(() -> FrameRange.parse(o.frames));
        String pattern = null;
        if (frames == null && o.resume) {
            throw new ParameterException(commandLine, "--resume is for --frames: it skips frames already written");
        }
        if (frames != null) {
            if (o.repeat != 1) {
                throw new ParameterException(commandLine, "--repeat is for a still; with --frames each frame is rendered once");
            }
            pattern = o.output != null ? o.output.toString() : FrameFiles.defaultPattern(o.scene);
            String why = FrameFiles.whyNotPattern(pattern);
            if (why != null) {
                throw new ParameterException(commandLine, "-o " + pattern + " cannot name the frames: " + why);
            }
        }
        Path out = frames != null ? FrameFiles.name(pattern, frames.first()) : o.output != null ? o.output : OutputFile.defaultFor(o.scene);
        // a bad -o is a bad option value, found before rendering, not after; the frames' files are
        // checked by FrameOutputs, once the scene says which frames there are and their size (--resume)
        String unwritable = frames != null ? null : OutputFile.whyUnwritable(out);
        if (unwritable != null) {
            throw new ParameterException(commandLine, "cannot write " + out + ": " + unwritable);
        }
        if (o.show) {
            // AWT is loaded here only, and only for --show: a run without it loads no AWT class
            String why = GraphicalDisplay.whyNone();
            if (why != null) {
                throw new ParameterException(commandLine, "--show needs a graphical display: " + why);
            }
        }
        return new RenderRequest(o.scene, out, options, threads, o.repeat, o.stats, o.options.quiet(), o.show, frames, pattern,
                                 o.resume);
    }

    private static boolean parseView(String view) {
        return switch (view) {
            case "shaded" -> false;
            case "bvh-cost" -> true;
            default -> throw new IllegalArgumentException("unknown view '" + view + "'; allowed: shaded, bvh-cost");
        };
    }

    /** Runs an option's parser, turning its complaint into a usage error. */
    private <T> T usage(Supplier<T> parse) {
        try {
            return parse.get();
        } catch (IllegalArgumentException e) {
            throw new ParameterException(commandLine, e.getMessage());
        }
    }

    private void requireAtLeast(String option, Integer value, int min) {
        if (value != null && value < min) {
            throw new ParameterException(commandLine, option + " must be at least " + min + ", got " + value);
        }
    }
}

package raytracer.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raytracer.cli.converge.ConvergeCommand;
import raytracer.cli.render.RenderRequest;
import raytracer.cli.render.RenderRun;

/**
 * {@code render [SCENE] -o FILE ...}: the program's entry point, render's own options as picocli
 * reads them, and the options it shares with converge and the Spark job ({@link RenderOptions},
 * {@link ImageOptions}). The options are checked by {@link OptionChecks}, the render is run by
 * {@link RenderRun}, and failures reach the user through {@link ErrorReport}.
 */
@Command(name = "render", mixinStandardHelpOptions = true, versionProvider = Version.class,
         sortOptions = false, subcommands = ConvergeCommand.class,
         description = "Renders a scene file (YAML or JSON) to PNG or PFM. Without SCENE, renders the built-in default scene.")
public final class RenderCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE", description = "Scene file (.yaml, .yml or .json).")
    Path scene;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE",
            description = "Output image, .png (sRGB 8-bit) or .pfm (linear float). Default: <scene name>.png")
    Path output;

    @Mixin
    ImageOptions image = new ImageOptions();

    @Mixin
    RenderOptions options = new RenderOptions();

    @Option(names = "--view", paramLabel = "VIEW",
            description = "What to show: shaded (default) or bvh-cost (the report's figure 9: the bounding-volume tests per pixel, "
                          + "the mean of its camera rays' searches, in false colour, brighter = more; the range is printed).")
    String view = "shaded";

    @Option(names = "--frames", paramLabel = "A-B",
            description = "Render frames A to B of the scene's animation (or one frame, A) in this JVM, the scene read once; "
                          + "-o is then a pattern with %%d or %%04d for the frame number. Default output: <scene name>-%%04d.png.")
    String frames;

    @Option(names = "--resume",
            description = "With --frames: skip the frames whose file is already a whole image of the run's size, checked to "
                          + "its last byte (an interrupted animation goes on); one damaged or of another size is rendered again, "
                          + "with a warning.")
    boolean resume;

    @Option(names = "--repeat", paramLabel = "N",
            description = "Render N times in this JVM and report each (benchmarking: the first render includes JIT warm-up).")
    int repeat = 1;

    @Option(names = "--show",
            description = "Show the image in a window as its tiles finish, as the file will hold it; the window stays "
                          + "until Esc or closed. Esc or closing it during the render cancels the render, as Ctrl-C does.")
    boolean show;

    @Option(names = "--stats", description = "Print a breakdown: load steps (parse, BVH build, mesh cache), render time, "
            + "rays by kind, BVH tests per ray, peak heap, and what the scene analysis left out and why.")
    boolean stats;

    @Spec
    CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(new PrintWriter(System.err, true), args));
    }

    /**
     * Runs the command, writing messages to {@code err}, and returns its exit code: 0 done, 1 bad
     * input or failed render, 2 bad usage.
     */
    public static int run(PrintWriter err, String... args) {
        return run(new PrintWriter(System.out, true), err, args);
    }

    /** As {@link #run(PrintWriter, String...)}, with standard output ({@code converge}'s table and {@code --csv -}) on {@code out}. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        return ErrorReport.install(new CommandLine(new RenderCommand()), out, err).execute(args);
    }

    @Override
    public Integer call() throws Exception {
        RenderRequest request = new OptionChecks(spec.commandLine()).check(this);
        return ErrorReport.explainingLimits(() -> new RenderRun(request, spec.commandLine()).run());
    }
}

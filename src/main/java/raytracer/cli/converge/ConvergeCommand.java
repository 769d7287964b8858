package raytracer.cli.converge;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raytracer.api.OutputFile;
import raytracer.api.SceneOptions;
import raytracer.cache.ReferenceCache;
import raytracer.cli.RenderOptions;
import raytracer.cli.Terminal;
import raytracer.cli.Version;
import raytracer.core.Sampler;
import raytracer.image.FileKind;

/**
 * {@code render converge SCENE ...}: renders a scene at several sample counts or time budgets, for
 * one or more configurations, measures each image's error against a reference and prints a table,
 * the slope of each curve, and a log-log plot of error against render time. This class holds the
 * options and checks them, every bad value a usage error found before any scene is read; the
 * options it shares with render are {@link RenderOptions}'s, worded for converge by
 * {@link ConvergeHelp}; {@link ConvergeRun} does the work.
 */
@Command(name = "converge", mixinStandardHelpOptions = true, versionProvider = Version.class, sortOptions = false,
         resourceBundle = "raytracer.cli.converge.ConvergeHelp",
         description = {"Renders SCENE at several sample counts (--spp) and/or time budgets (--time), for each configuration "
                        + "(--config), compares each image with a reference and prints a table of the errors; writes a log-log "
                        + "plot of relative RMSE against render time, one curve per configuration.",
                        "Seconds are the render's wall time (scene loading and BVH building excluded); before the timed renders "
                        + "of a configuration, one untimed render at its smallest sample count (at least 4) warms the JIT up."},
         footer = {"", "Metrics, over all pixels and the 3 channels of linear radiance times the scene's exposure (n values x_i, "
                   + "reference r_i):",
                   "  RMSE = sqrt(sum (x_i - r_i)^2 / n);  relative RMSE = RMSE / mean(r_i);",
                   "  relative MSE = sum ((x_i - r_i)^2 / (r_i^2 + 0.01)) / n (pbrt's; the 0.01 spares black pixels);",
                   "  worst pixel = the largest |x_i - r_i|, at (column, row) from the top left.",
                   "Slope: least squares of log(relative RMSE) against log(seconds); independent samples give -0.5."})
public final class ConvergeCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file (.yaml, .yml or .json).")
    Path scene;

    @Option(names = {"-s", "--spp"}, split = ",", paramLabel = "N",
            description = "Sample counts per pixel, comma-separated (square patterns round up to a square). "
                          + "Default: 1,4,16,64 unless --time is given.")
    List<Integer> spp = new ArrayList<>();

    @Option(names = "--time", split = ",", paramLabel = "SECONDS",
            description = "Time budgets: for each, the sample count that the configuration's last render says fits in it.")
    List<Double> budgets = new ArrayList<>();

    @Option(names = "--config", paramLabel = "KEY=VALUE[,...]",
            description = "A configuration (repeat for more): sampler=NAME (a name --sampler takes), light-samples=N per "
                          + "area light, cutoff=C, label=TEXT; a/b in a value makes one configuration per alternative. "
                          + "Default: the scene's own settings (with --sampler and --cutoff).")
    List<String> configs = new ArrayList<>();

    @Option(names = "--reference", paramLabel = "REF",
            description = "auto (default: closed-form when the scene has an exact image, else self), closed-form, self "
                          + "(the scene rendered at --reference-spp, in two halves with other seeds whose difference measures "
                          + "its own noise, and cached), or a .pfm file of the image's size.")
    String reference = "auto";

    @Option(names = "--reference-spp", paramLabel = "N", description = "Samples per pixel of a self-rendered reference. Default: ${DEFAULT-VALUE}.")
    int referenceSpp = 4096;

    @Option(names = "--cache", paramLabel = "DIR",
            description = "Folder of self-rendered references. Default: $XDG_CACHE_HOME/raytracer/references or ~/.cache/raytracer/references.")
    Path cacheDir;

    @Option(names = "--plot", paramLabel = "FILE.png", description = "The log-log plot. Default: <scene name>-convergence.png")
    Path plot;

    @Option(names = "--csv", paramLabel = "FILE",
            description = "Also write the table as comma-separated values; - writes them to standard output, alone (the table "
                          + "then goes to standard error).")
    Path csv;

    @Option(names = "--metric", paramLabel = "M",
            description = "What the errors are measured on: linear (radiance, as the .pfm output holds it; the default) or srgb "
                          + "(the display's values, clamped and sRGB-encoded, as a PNG holds them).")
    String metric = "linear";

    @Option(names = "--frame", paramLabel = "N",
            description = "The frame of an animated scene to converge, from 0. Default: 0, the frame render renders without --frames.")
    int frame;

    /** The size, filter, seed, search, mesh cache, threads and talk of every render, render's options. */
    @Mixin
    RenderOptions options = new RenderOptions();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            ConvergeRun run = checked();
            return run.run();
        } catch (CommandLine.ParameterException e) {
            throw e;
        } catch (Exception | OutOfMemoryError e) {
            String message = e instanceof OutOfMemoryError
                ? "out of memory; give Java more heap, e.g. java -Xmx8g -jar render.jar converge ..."
                : e.getMessage() == null || e.getMessage().isBlank() ? e.getClass().getSimpleName() : e.getMessage();
            err.println("render converge: error: " + Terminal.line(message));
            if (options.verbose()) {
                e.printStackTrace(err);
            }
            return 1;
        }
    }

    /** The options checked, and the run they ask for; bad values are usage errors (exit code 2). */
    private ConvergeRun checked() {
        if (spp.isEmpty() && budgets.isEmpty()) {
            spp = new ArrayList<>(List.of(1, 4, 16, 64));
        }
        for (int n : spp) {
            usageIf(n < 1 || n > Sampler.MAX_SAMPLES, "--spp values must be 1 to " + Sampler.MAX_SAMPLES + ", got " + n);
        }
        for (double t : budgets) {
            usageIf(!(t > 0) || Double.isInfinite(t), "--time values must be positive seconds, got " + t);
        }
        int threads = options.threads();
        SceneOptions sceneOptions = options.sceneOptions(null, false);
        usageIf(!List.of("linear", "srgb").contains(metric), "--metric must be linear or srgb, got '" + metric + "'");
        // rendered in two halves of half the count each
        usageIf(referenceSpp < 1 || referenceSpp > 2 * Sampler.MAX_SAMPLES, "--reference-spp must be 1 to "
                + 2 * Sampler.MAX_SAMPLES + ", got " + referenceSpp);
        usageIf(cacheDir != null && cacheDir.toString().isEmpty(), "--cache must name a folder, got an empty name");
        FileKind cacheKind = cacheDir == null ? FileKind.MISSING : FileKind.of(cacheDir);
        usageIf(cacheKind != FileKind.DIRECTORY && cacheKind != FileKind.MISSING,
                "--cache " + cacheDir + " is " + cacheKind.words() + ", not a folder");
        usageIf(!List.of("auto", "closed-form", "self").contains(reference) && !reference.toLowerCase(Locale.ROOT).endsWith(".pfm"),
                "--reference must be auto, closed-form, self or a .pfm file, got '" + reference + "'");
        spp = new ArrayList<>(new TreeSet<>(spp));
        budgets = new ArrayList<>(new TreeSet<>(budgets));
        List<ConvergeConfig> curves = curves();
        Path plotFile = plot != null ? plot : Path.of(stem(scene) + "-convergence.png");
        checkOutputs(plotFile);
        ReferenceCache cache = options.noCache() ? null
            : new ReferenceCache(cacheDir != null ? cacheDir : ReferenceCache.defaultDir(System.getenv(), System.getProperty("user.home")));
        return new ConvergeRun(this, curves, sceneOptions, threads, cache, plotFile);
    }

    /** The configurations to measure: --config's, or the scene's own. */
    private List<ConvergeConfig> curves() {
        if (configs.isEmpty()) {
            return List.of(ConvergeConfig.SCENE);
        }
        List<ConvergeConfig> curves = new ArrayList<>();
        for (String text : configs) {
            try {
                curves.addAll(ConvergeConfig.parse(text));
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
            }
        }
        return curves;
    }

    /** Fails before the first render, not after the last, when an output could not be written: a usage error. */
    private void checkOutputs(Path plotFile) {
        usageIf(!plotFile.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png"),
                "cannot write " + plotFile + ": the plot is a PNG file, give a name ending in .png");
        String why = OutputFile.whyNotWritable(plotFile);
        usageIf(why != null, "cannot write " + plotFile + ": " + why);
        if (csv != null && !csvToStdout()) {
            why = OutputFile.whyNotWritable(csv);
            usageIf(why != null, "cannot write " + csv + ": " + why);
            usageIf(OutputFile.same(csv, plotFile), "--plot and --csv name the same file, " + csv);
        }
    }

    /** True for {@code --csv -}: standard output is the CSV alone. */
    boolean csvToStdout() {
        return csv != null && csv.toString().equals("-");
    }

    /** True when errors are taken on the displayed values ({@code --metric srgb}) rather than on radiance. */
    boolean displayedMetric() {
        return metric.equals("srgb");
    }

    /** A usage error of this command (exit code 2) when {@code bad}. */
    void usageIf(boolean bad, String message) {
        if (bad) {
            throw new CommandLine.ParameterException(spec.commandLine(), message);
        }
    }

    private static String stem(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }
}

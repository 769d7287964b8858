package raytracer.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/**
 * How failures reach the user: one line on stderr starting {@code render: error:}, exit code 2 for
 * a bad option (with a pointer to --help) and 1 for bad input or a failed render, and the stack
 * trace only with {@code --verbose}. A render cancelled from the --show window exits 130, as on SIGINT.
 */
public final class ErrorReport {
    public static final int BAD_INPUT = 1;
    public static final int BAD_USAGE = 2;
    /** What the JVM exits with on SIGINT (128 + 2): a render cancelled from the --show window ends as Ctrl-C ends it. */
    public static final int INTERRUPTED = 130;

    private ErrorReport() {
    }

    /**
     * Makes {@code cli} report its failures on {@code err} as above, and print on {@code err} and
     * {@code out} through {@link Terminal#escaping} (echoed names cannot drive the terminal); returns it.
     */
    static CommandLine install(CommandLine cli, PrintWriter out, PrintWriter err) {
        cli.setErr(new PrintWriter(Terminal.escaping(err), true));
        cli.setOut(new PrintWriter(Terminal.escaping(out), true));
        cli.setParameterExceptionHandler((ex, args) -> {
            ex.getCommandLine().getErr().println("render: error: " + Terminal.line(ex.getMessage()) + " (see render --help)");
            return BAD_USAGE;
        });
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            commandLine.getErr().println("render: error: " + oneLine(ex));
            if (verbose(commandLine)) {
                ex.printStackTrace(commandLine.getErr());
            }
            return BAD_INPUT;
        });
        return cli;
    }

    /**
     * Runs {@code work}, turning the two errors that a scene can cause beyond its own mistakes into
     * messages that say what to change: recursion deeper than a thread's stack, and too little heap.
     */
    static <T> T explainingLimits(Callable<T> work) throws Exception {
        try {
            return work.call();
        } catch (StackOverflowError e) {
            throw new IllegalStateException("the recursion went deeper than a worker thread's stack holds; lower the "
                                            + "scene's max-depth or --max-depth", e);
        } catch (OutOfMemoryError e) {
            // the film and the scene are unreachable now, so there is memory to say so
            throw new IllegalStateException("out of memory for this scene and image size; give Java more heap, e.g. "
                                            + "java -Xmx8g -jar render.jar ... (now at most "
                                            + Runtime.getRuntime().maxMemory() / (1024 * 1024) + " MiB)", e);
        }
    }

    private static boolean verbose(CommandLine commandLine) {
        OptionSpec option = commandLine.getCommandSpec().findOption("--verbose");
        return option != null && Boolean.TRUE.equals(option.getValue());
    }

    /** The exception's message on one bounded line ({@link Terminal#line}), or its class name when it has none. */
    static String oneLine(Throwable ex) {
        String message = ex.getMessage();
        if (message == null || message.isBlank()) {
            message = ex.getClass().getSimpleName();
        }
        return Terminal.line(message);
    }
}

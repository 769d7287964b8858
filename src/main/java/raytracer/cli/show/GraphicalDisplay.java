package raytracer.cli.show;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Whether {@code --show} can open a window, asked before any work. The only class besides
 * {@link ShowWindow} that touches AWT, and only with {@code --show}: a run without it loads no AWT
 * class (ShowWithoutDisplayTest checks).
 */
public final class GraphicalDisplay {
    /**
     * How long the display may take to answer. A display over a slow ssh -X link answers in well
     * under a second; one that accepts the connection and never answers (a stalled X server, a
     * dead forward) would otherwise block the run for ever before any work.
     */
    public static final int ANSWER_SECONDS = 5;

    private GraphicalDisplay() {
    }

    /** Why no window can be opened, or null when one can; at most {@value #ANSWER_SECONDS} s. */
    public static String whyNone() {
        // Xlib's connection cannot be interrupted: the check runs in a daemon thread, left behind if it hangs
        FutureTask<String> check = new FutureTask<>(GraphicalDisplay::connect);
        Thread thread = new Thread(check, "display check");
        thread.setDaemon(true);
        thread.start();
        try {
            return check.get(ANSWER_SECONDS, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            return "the display DISPLAY=" + System.getenv("DISPLAY") + " did not answer in " + ANSWER_SECONDS
                   + " s (a stalled X server or a dead ssh -X forward?)";
        } catch (ExecutionException e) {
            return "cannot connect to the display DISPLAY=" + System.getenv("DISPLAY") + " (" + e.getCause() + ")";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted while connecting to the display";
        }
    }

    private static String connect() {
        if (GraphicsEnvironment.isHeadless()) {
            return Boolean.getBoolean("java.awt.headless") ? "Java is told to run headless (-Djava.awt.headless=true)"
                   : "DISPLAY is not set";
        }
        try {
            // connects to the display: an X server that is not there fails here
            GraphicsEnvironment.getLocalGraphicsEnvironment().getDefaultScreenDevice();
            return null;
        } catch (UnsatisfiedLinkError e) {
            return "this Java has no graphical libraries (a headless JDK; install the full one, e.g. openjdk-17-jre)";
        } catch (Error e) {
            // AWTError "Can't connect to X11 window server ...", or the class left unusable by it
            return "cannot connect to the display DISPLAY=" + System.getenv("DISPLAY");
        }
    }
}

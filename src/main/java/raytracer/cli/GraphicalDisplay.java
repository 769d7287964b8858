package raytracer.cli;

import java.awt.GraphicsEnvironment;

/**
 * Whether {@code --show} can open a window, asked before any work. The only class besides
 * {@link ShowWindow} that touches AWT, and only with {@code --show}: a run without it loads no AWT
 * class (cli.ShowWithoutDisplayTest checks).
 */
final class GraphicalDisplay {
    private GraphicalDisplay() {
    }

    /** Why no window can be opened, or null when one can. */
    static String whyNone() {
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

package raytracer.cli.show;

import java.awt.Component;
import java.awt.Frame;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.KeyEvent;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import raytracer.cli.RenderCommand;

/**
 * A JVM started on a display by {@link ShowWindowTest}: runs {@code render ... --show} on one thread
 * and acts on its window from another, as a user would, with {@link Robot} (the X server's XTEST).
 * <ul>
 *   <li>{@code capture FILE ARGS...}: waits until the window says the render is done, writes the
 *       window's pixels as read back from the screen to FILE (a PNG), presses Esc and exits with the
 *       command's status;</li>
 *   <li>{@code escape - ARGS...}: presses Esc as soon as the window shows a finished tile, while the
 *       render runs: the command exits the JVM itself;</li>
 *   <li>{@code close - ARGS...}: the same with the window's close button (a WINDOW_CLOSING event, as
 *       a window manager sends it: Xvfb runs none).</li>
 * </ul>
 * Exit 97 when the window never appeared, 98 when the command outlived its cancel.
 */
final class ShowCapture {
    private static final long TIMEOUT_NANOS = 60_000_000_000L;

    private ShowCapture() {
    }

    public static void main(String[] args) throws Exception {
        String mode = args[0];
        String[] renderArgs = Arrays.copyOfRange(args, 2, args.length);
        AtomicReference<Integer> status = new AtomicReference<>();
        Thread render = new Thread(() -> status.set(RenderCommand.run(new PrintWriter(System.err, true), renderArgs)), "render");
        render.start();
        Robot robot = new Robot();
        JFrame frame = awaitWindow(mode.equals("capture") ? "done in" : "%", render);
        if (frame == null) {
            render.join(1000);
            System.exit(status.get() != null && status.get() != 0 ? status.get() : 97);
        }
        Component picture = onEventThread(() -> frame.getContentPane().getComponent(0));
        Rectangle shown = onEventThread(() -> {
            Point at = picture.getLocationOnScreen();
            return new Rectangle(at.x, at.y, picture.getPreferredSize().width, picture.getPreferredSize().height);
        });
        if (mode.equals("capture")) {
            ImageIO.write(steadyCapture(robot, shown, picture), "png", Path.of(args[1]).toFile());
        }
        if (mode.equals("close")) {
            SwingUtilities.invokeLater(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        } else {
            // the pointer over the window gives it the keyboard under X's default focus, pointer-root
            robot.mouseMove(shown.x + shown.width / 2, shown.y + shown.height / 2);
            robot.waitForIdle();
            onEventThread(() -> {
                frame.toFront();
                frame.requestFocus();
                return null;
            });
            robot.waitForIdle();
            robot.keyPress(KeyEvent.VK_ESCAPE);
            robot.keyRelease(KeyEvent.VK_ESCAPE);
        }
        render.join(mode.equals("capture") ? 30_000 : 20_000);
        System.exit(mode.equals("capture") && status.get() != null ? status.get() : 98);
    }

    /**
     * The shown window once its title contains {@code titled}, or null if the render ended without
     * one, or if the window said it was done when {@code titled} is what it says while rendering.
     */
    private static JFrame awaitWindow(String titled, Thread render) throws Exception {
        long end = System.nanoTime() + TIMEOUT_NANOS;
        while (System.nanoTime() < end) {
            String[] title = new String[1];
            JFrame found = onEventThread(() -> {
                for (Frame f : Frame.getFrames()) {
                    if (f instanceof JFrame j && j.isShowing()) {
                        title[0] = j.getTitle();
                        return j;
                    }
                }
                return null;
            });
            if (found != null && title[0].contains(titled)) {
                return found;
            }
            if (found != null && title[0].contains("done in")) {
                System.err.println("show-capture: the render was done before the window could be closed");
                return null;
            }
            if (!render.isAlive()) {
                return null;
            }
            Thread.sleep(20);
        }
        return null;
    }

    /**
     * The screen's pixels in {@code r} once two reads 100 ms apart agree (the last repaint has reached
     * the server) and show more than one colour: on a loaded machine a window can be mapped, and
     * titled done, before its picture is first painted, and two reads of the bare background agree.
     * None of the tests' images is one flat colour. A busy machine can take seconds to paint, or
     * lose the paint (all-black captures were seen after 5 s and after 60 s), so while the read is
     * flat the picture is asked to repaint, for as long as the window's own wait: the first read
     * that passes is taken. If the screen is still flat then (two CPU-bound processes beside the
     * suite left an Xvfb window unpainted for a minute), the picture's own painting is taken
     * instead, as the window would draw it, and a line says so: the pixels the window holds are
     * still checked, the X server's timing no longer decides the test.
     */
    private static BufferedImage steadyCapture(Robot robot, Rectangle r, Component picture) throws Exception {
        robot.waitForIdle();
        BufferedImage before = robot.createScreenCapture(r);
        for (long end = System.nanoTime() + TIMEOUT_NANOS; System.nanoTime() < end; ) {
            Thread.sleep(100);
            robot.waitForIdle();
            BufferedImage now = robot.createScreenCapture(r);
            int[] shown = pixels(now);
            if (Arrays.equals(pixels(before), shown) && !flat(shown)) {
                return now;
            }
            if (flat(shown)) {
                // an expose event lost under load leaves the mapped window unpainted: ask for the paint again
                SwingUtilities.invokeLater(picture::repaint);
                java.awt.Toolkit.getDefaultToolkit().sync();
            }
            before = now;
        }
        System.err.println("show-capture: the screen stayed unpainted for " + TIMEOUT_NANOS / 1_000_000_000L
                           + " s; the window's own painting is compared instead");
        return onEventThread(() -> {
            BufferedImage painted = new BufferedImage(r.width, r.height, BufferedImage.TYPE_INT_RGB);
            java.awt.Graphics2D g = painted.createGraphics();
            picture.paint(g);
            g.dispose();
            return painted;
        });
    }

    private static boolean flat(int[] rgb) {
        for (int p : rgb) {
            if (p != rgb[0]) {
                return false;
            }
        }
        return true;
    }

    private static int[] pixels(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private interface Work<T> {
        T get() throws Exception;
    }

    private static <T> T onEventThread(Work<T> work) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                result.set(work.get());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        return result.get();
    }
}

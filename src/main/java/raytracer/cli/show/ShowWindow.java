package raytracer.cli.show;

import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.GraphicsEnvironment;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.lang.reflect.InvocationTargetException;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.function.DoubleSupplier;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import raytracer.cli.Progress;
import raytracer.image.Film;
import raytracer.render.TileListener;

/**
 * The {@code --show} window: the image as its tiles finish, then the final image until Esc or the
 * close button. The workers only queue each finished tile ({@link #tileDone}); a Swing timer on the
 * event thread takes the queue at most {@link #REPAINT_MILLIS} apart, codes those tiles' pixels and
 * repaints them, so the render pays one queue entry per tile. The frames of an animation are
 * rendered into the same film and shown one after another ({@link #startFrame}). Esc or closing
 * the window before {@link #finish} cancels the run through {@code cancel}; after it, closes the window.
 */
public final class ShowWindow implements TileListener, AutoCloseable {
    /** At most ten repaints a second: smooth enough to watch, and nothing a render could measure. */
    static final int REPAINT_MILLIS = 100;
    private static final long TITLE_NANOS = 500_000_000L;

    private final String scene;
    private final Film film;
    private final ShowTone tone;
    private final ShowTone last;
    private final DoubleSupplier progress;
    private final Runnable cancel;
    private final Queue<int[]> finished = new ConcurrentLinkedQueue<>();
    private final CountDownLatch closed = new CountDownLatch(1);
    private final long start = System.nanoTime();
    /** The frame being shown ("frame 12"), empty for a still. */
    private volatile String frameLabel = "";

    // the event thread's alone
    private final List<int[]> shownTiles = new ArrayList<>();
    private JFrame frame;
    private Picture picture;
    private ShowPixels pixels;
    private Timer timer;
    private boolean done;
    private long titled = Long.MIN_VALUE / 2;

    private ShowWindow(String scene, Film film, ShowTone tone, ShowTone last, DoubleSupplier progress, Runnable cancel) {
        this.scene = scene;
        this.film = film;
        this.tone = tone;
        this.last = last;
        this.progress = progress;
        this.cancel = cancel;
    }

    /**
     * Opens the window on {@code film}, titled with {@code scene}; the file's codes are those of
     * {@code exposure} and {@code srgb}, and of the false colour in the {@code costView}, whose
     * range is known at the end only. {@code progress} gives the fraction done and {@code cancel}
     * stops the run.
     */
    public static ShowWindow open(String scene, Film film, boolean costView, double exposure, boolean srgb, DoubleSupplier progress,
                           Runnable cancel) throws Exception {
        ShowTone last = ShowTone.png(exposure, srgb);
        ShowWindow window = new ShowWindow(scene, film, costView ? new ShowCostTone() : last, last, progress, cancel);
        onEventThread(window::build);
        return window;
    }

    private void build() {
        frame = new JFrame(scene);
        frame.setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        frame.addNotify(); // the decorations' insets are known from here on
        Insets insets = frame.getInsets();
        Rectangle screen = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        int[] size = ShowScale.fit(film.width(), film.height(), screen.width - insets.left - insets.right,
                                   screen.height - insets.top - insets.bottom);
        BufferedImage image = new BufferedImage(size[0], size[1], BufferedImage.TYPE_INT_RGB);
        pixels = new ShowPixels(film.width(), film.height(), size[0], size[1],
                                ((DataBufferInt) image.getRaster().getDataBuffer()).getData());
        picture = new Picture(image);
        frame.add(picture);
        frame.getRootPane().registerKeyboardAction(e -> escape(), KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0),
                                                   JComponent.WHEN_IN_FOCUSED_WINDOW);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                escape();
            }
        });
        frame.pack();
        frame.setLocationRelativeTo(null);
        frame.setVisible(true);
        timer = new Timer(REPAINT_MILLIS, e -> showFinishedTiles());
        timer.start();
    }

    /**
     * A new frame is about to be rendered into the film: its tiles replace the last frame's as
     * they finish, and the title names it ({@code label}: "frame 12").
     */
    public void startFrame(String label) {
        frameLabel = label.isEmpty() ? "" : " " + label;
        SwingUtilities.invokeLater(shownTiles::clear);
    }

    /** On a worker: queue the tile for the event thread. */
    @Override
    public void tileDone(int x0, int y0, int x1, int y1) {
        finished.add(new int[] {x0, y0, x1, y1});
    }

    private void showFinishedTiles() {
        if (done) {
            return;
        }
        List<int[]> fresh = new ArrayList<>();
        for (int[] tile = finished.poll(); tile != null; tile = finished.poll()) {
            fresh.add(tile);
        }
        boolean again = false;
        for (int[] tile : fresh) {
            again |= tone.takeIn(film, tile[0], tile[1], tile[2], tile[3]);
        }
        shownTiles.addAll(fresh);
        for (int[] tile : again ? shownTiles : fresh) {
            int[] changed = pixels.update(film, tile[0], tile[1], tile[2], tile[3], tone);
            if (!again) {
                picture.drawNow(changed);
            }
        }
        if (again) {
            picture.repaint();
        }
        long now = System.nanoTime();
        if (now - titled >= TITLE_NANOS) {
            // a title took about 2 ms to set under Xvfb, four tiles' drawing: twice a second is enough to read
            titled = now;
            double f = progress.getAsDouble();
            double seconds = (now - start) / 1e9;
            String left = f > 0.01 ? Progress.formatSeconds(seconds * (1 - f) / f) + " left" : "time left unknown";
            frame.setTitle(String.format("%s%s: %.0f%%, %s", scene, frameLabel, 100 * f, left));
        }
    }

    /**
     * The render is over and its file written: shows {@code written}, the film as the file holds
     * it, in the file's codes, and from now on Esc and the close button close the window.
     */
    public void finish(Film written) throws Exception {
        double seconds = (System.nanoTime() - start) / 1e9;
        onEventThread(() -> {
            timer.stop();
            done = true;
            pixels.update(written, 0, 0, written.width(), written.height(), last);
            picture.repaint();
            frame.setTitle(String.format("%s: done in %s (Esc closes)", scene, Progress.formatSeconds(seconds)));
        });
    }

    /** Waits until the window is closed after {@link #finish}. */
    public void awaitClose() throws InterruptedException {
        closed.await();
    }

    private void escape() {
        if (!done) {
            cancel.run();
            return;
        }
        frame.dispose();
        closed.countDown();
    }

    /** Closes the window whatever state it is in (the run ended, or failed). */
    @Override
    public void close() {
        SwingUtilities.invokeLater(() -> {
            if (timer != null) {
                timer.stop();
            }
            if (frame != null) {
                frame.dispose();
            }
        });
        closed.countDown();
    }

    private static void onEventThread(Runnable work) throws Exception {
        try {
            SwingUtilities.invokeAndWait(work);
        } catch (InvocationTargetException e) {
            throw e.getCause() instanceof Exception cause ? cause : e;
        }
    }

    /** The shown pixels, drawn one to one. */
    private static final class Picture extends JComponent {
        private static final long serialVersionUID = 1L;
        private final transient BufferedImage image;

        Picture(BufferedImage image) {
            this.image = image;
            setPreferredSize(new Dimension(image.getWidth(), image.getHeight()));
        }

        @Override
        protected void paintComponent(Graphics g) {
            g.drawImage(image, 0, 0, null);
        }

        /**
         * Draws the pixels of rectangle {x, y, width, height} straight to the screen, without
         * Swing's repaint: repaint() would merge the tiles of a tick, spread over the image by the
         * tile order, into one rectangle of nearly the whole image, and draw it through a back
         * buffer.
         */
        void drawNow(int[] r) {
            Graphics g = getGraphics();
            if (g != null) {
                g.drawImage(image, r[0], r[1], r[0] + r[2], r[1] + r[3], r[0], r[1], r[0] + r[2], r[1] + r[3], null);
                g.dispose();
            }
        }
    }
}

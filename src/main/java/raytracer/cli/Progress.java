package raytracer.cli;

import java.io.PrintStream;
import java.util.function.DoubleSupplier;

/**
 * A one-line progress bar with percentage and ETA, redrawn on stderr a few times a second by a
 * daemon thread. It stays silent for renders shorter than about a second.
 */
public final class Progress implements AutoCloseable {
    private static final long FIRST_DRAW_NANOS = 1_000_000_000L;
    private static final int WIDTH = 30;

    private final PrintStream out;
    private final String label;
    private final DoubleSupplier fraction;
    private final Thread thread;
    private final long start = System.nanoTime();
    private volatile boolean running = true;
    private boolean drawn;

    public Progress(PrintStream out, DoubleSupplier fraction) {
        this(out, "", fraction);
    }

    /** A bar preceded by {@code label} (which render of several this is). */
    public Progress(PrintStream out, String label, DoubleSupplier fraction) {
        this.out = out;
        this.label = label.isEmpty() ? "" : label + " ";
        this.fraction = fraction;
        this.thread = new Thread(this::loop, "progress");
        thread.setDaemon(true);
        thread.start();
    }

    private void loop() {
        while (running) {
            try {
                Thread.sleep(250);
            } catch (InterruptedException e) {
                return;
            }
            long elapsed = System.nanoTime() - start;
            if (running && elapsed > FIRST_DRAW_NANOS) {
                draw(fraction.getAsDouble(), elapsed);
            }
        }
    }

    private synchronized void draw(double f, long elapsedNanos) {
        int filled = (int) Math.round(f * WIDTH);
        double seconds = elapsedNanos / 1e9;
        String eta = f > 0.01 ? formatSeconds(seconds * (1 - f) / f) : "--";
        out.print("\r" + label + "[" + "#".repeat(filled) + " ".repeat(WIDTH - filled) + "] "
                  + String.format("%5.1f%%  elapsed %s  ETA %s ", 100 * f, formatSeconds(seconds), eta));
        out.flush();
        drawn = true;
    }

    public static String formatSeconds(double s) {
        if (s < 60) {
            return String.format("%.1fs", s);
        }
        long total = Math.round(s);
        return String.format("%dm%02ds", total / 60, total % 60);
    }

    @Override
    public synchronized void close() {
        running = false;
        thread.interrupt();
        if (drawn) {
            out.print("\r" + " ".repeat(label.length() + WIDTH + 50) + "\r");
            out.flush();
        }
    }
}

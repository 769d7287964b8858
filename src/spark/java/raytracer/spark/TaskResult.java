package raytracer.spark;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import raytracer.render.RenderStats;
import raytracer.render.TilePixels;

/**
 * What a task hands back to the driver, as bytes of our own layout, so that the result travels in
 * any serializer Spark is given and the driver needs none of our classes to receive it: a frame
 * written whole (its file and size), a run of tiles (their pixels or a wider filter's sums, to the
 * bit), or a scene error (its one-line message; the task is not retried, since it would fail
 * again). Each carries the render's counts and where the executor's SnakeYAML came from.
 */
final class TaskResult {
    static final int WRITTEN = 0;
    static final int TILES = 1;
    static final int FAILED = 2;

    final int kind;
    final int frame;
    final String text;
    final long bytes;
    final long primaryRays;
    final long nonFiniteSamples;
    final long renderNanos;
    /** The time this task spent reading the scene (0 when the executor had it), and the whole task's time. */
    final long sceneNanos;
    final long taskNanos;
    final String yaml;
    final List<TilePixels> tiles;

    private TaskResult(int kind, int frame, String text, long bytes, long primaryRays, long nonFiniteSamples, long renderNanos,
                       long sceneNanos, long taskNanos, String yaml, List<TilePixels> tiles) {
        this.kind = kind;
        this.frame = frame;
        this.text = text;
        this.bytes = bytes;
        this.primaryRays = primaryRays;
        this.nonFiniteSamples = nonFiniteSamples;
        this.renderNanos = renderNanos;
        this.sceneNanos = sceneNanos;
        this.taskNanos = taskNanos;
        this.yaml = yaml;
        this.tiles = tiles;
    }

    /** Frame {@code frame} written whole to {@code file}, {@code bytes} long. */
    static byte[] written(int frame, String file, long bytes, RenderStats stats, long sceneNanos, long taskNanos, String yaml) {
        return new TaskResult(WRITTEN, frame, file, bytes, stats.primaryRays(), stats.nonFiniteSamples(), stats.wallNanos(), sceneNanos,
                              taskNanos, yaml, List.of()).encode();
    }

    /** Tiles of frame {@code frame}. */
    static byte[] tiles(int frame, TilePixels[] tiles, RenderStats stats, long sceneNanos, long taskNanos, String yaml) {
        return new TaskResult(TILES, frame, "", 0, stats.primaryRays(), stats.nonFiniteSamples(), stats.wallNanos(), sceneNanos,
                              taskNanos, yaml, List.of(tiles)).encode();
    }

    /** A scene error: its message. */
    static byte[] failed(int frame, String message, String yaml) {
        return new TaskResult(FAILED, frame, message, 0, 0, 0, 0, 0, 0, yaml, List.of()).encode();
    }

    private byte[] encode() {
        byte[] textBytes = text.getBytes(StandardCharsets.UTF_8);
        byte[] yamlBytes = yaml.getBytes(StandardCharsets.UTF_8);
        long size = 5L * 4 + 6 * 8 + textBytes.length + yamlBytes.length;
        for (TilePixels t : tiles) {
            size += 4 * 6 + 4 + (t.isBox() ? 4L * t.rgb().length : 8L * t.sums().length);
        }
        if (size > Integer.MAX_VALUE - 16) {
            throw new IllegalStateException("a task's tiles take " + size + " bytes, more than one array holds: give more tasks (--tasks)");
        }
        ByteBuffer out = ByteBuffer.allocate((int) size);
        out.putInt(kind).putInt(frame).putLong(bytes).putLong(primaryRays).putLong(nonFiniteSamples).putLong(renderNanos);
        out.putLong(sceneNanos).putLong(taskNanos);
        out.putInt(textBytes.length).put(textBytes).putInt(yamlBytes.length).put(yamlBytes);
        out.putInt(tiles.size());
        for (TilePixels t : tiles) {
            out.putInt(t.index()).putInt(t.x0()).putInt(t.y0()).putInt(t.x1()).putInt(t.y1()).putInt(t.isBox() ? 0 : 1);
            if (t.isBox()) {
                out.putInt(t.rgb().length);
                out.asFloatBuffer().put(t.rgb());
                out.position(out.position() + 4 * t.rgb().length);
            } else {
                out.putInt(t.sums().length);
                out.asDoubleBuffer().put(t.sums());
                out.position(out.position() + 8 * t.sums().length);
            }
        }
        return out.array();
    }

    static TaskResult decode(byte[] bytes) {
        ByteBuffer in = ByteBuffer.wrap(bytes);
        int kind = in.getInt();
        int frame = in.getInt();
        long size = in.getLong();
        long primary = in.getLong();
        long nonFinite = in.getLong();
        long nanos = in.getLong();
        long sceneNanos = in.getLong();
        long taskNanos = in.getLong();
        String text = string(in);
        String yaml = string(in);
        int count = in.getInt();
        List<TilePixels> tiles = new ArrayList<>(count);
        for (int k = 0; k < count; k++) {
            int index = in.getInt();
            int x0 = in.getInt();
            int y0 = in.getInt();
            int x1 = in.getInt();
            int y1 = in.getInt();
            boolean box = in.getInt() == 0;
            int length = in.getInt();
            if (box) {
                float[] rgb = new float[length];
                in.asFloatBuffer().get(rgb);
                in.position(in.position() + 4 * length);
                tiles.add(TilePixels.box(index, x0, y0, x1, y1, rgb));
            } else {
                double[] sums = new double[length];
                in.asDoubleBuffer().get(sums);
                in.position(in.position() + 8 * length);
                tiles.add(TilePixels.filtered(index, x0, y0, x1, y1, sums));
            }
        }
        return new TaskResult(kind, frame, text, size, primary, nonFinite, nanos, sceneNanos, taskNanos, yaml, tiles);
    }

    private static String string(ByteBuffer in) {
        byte[] b = new byte[in.getInt()];
        in.get(b);
        return new String(b, StandardCharsets.UTF_8);
    }
}

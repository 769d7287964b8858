package raytracer.spark;

import java.net.URL;
import java.nio.file.Path;
import org.apache.hadoop.conf.Configuration;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.function.Function;
import raytracer.api.ImageSettings;
import raytracer.api.Scene;
import raytracer.api.SceneFrame;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.SceneException;
import raytracer.render.RenderStats;
import raytracer.render.RenderedTiles;
import raytracer.render.Workers;

/**
 * One task on an executor: a frame rendered whole and written to its file, or a run of a frame's
 * tile list rendered into arrays for the driver. Task {@code {frame, from, to}}: tiles
 * {@code from} .. {@code to - 1} of the frame's list, or the whole frame when {@code from} is -1.
 * The scene comes from the executor's cache ({@link ExecutorScenes}); the result is bytes
 * ({@link TaskResult}). A scene error comes back as a result, not an exception: a retry would only
 * fail again, and the driver prints it as one line.
 */
final class FrameTask implements Function<int[], byte[]> {
    private static final long serialVersionUID = 1L;
    /**
     * A test's hook (a local property of the job): the first attempt of the task of this index fails,
     * a frame task having left a temporary file as a writer killed mid-file would.
     */
    static final String FAIL_FIRST_ATTEMPT = "raytracer.test.failFirstAttempt";

    private final Job job;

    FrameTask(Job job) {
        this.job = job;
    }

    @Override
    public byte[] call(int[] task) throws Exception {
        long start = System.nanoTime();
        int frame = task[0];
        TaskContext context = TaskContext.get();
        long[] sceneNanos = new long[1];
        int threads = job.threads > 0 ? job.threads : context == null ? 1 : Math.max(1, context.cpus());
        try (Workers workers = new Workers(threads)) {
            if (task[1] < 0) {
                return whole(frame, workers, context, sceneNanos, start);
            }
            int[] tiles = new int[task[2] - task[1]];
            for (int i = 0; i < tiles.length; i++) {
                tiles[i] = task[1] + i;
            }
            SceneFrame prepared = ExecutorScenes.prepared(job, frame, workers, sceneNanos);
            String input = Outputs.whyInput(job.output(frame), prepared.report().inputs());
            if (input != null) {
                return TaskResult.failed(frame, input, yamlSource());
            }
            failIfHooked(context, null);
            RenderedTiles rendered = prepared.renderer(workers).renderTiles(tiles);
            return TaskResult.tiles(frame, rendered.tiles(), rendered.stats(), sceneNanos[0], System.nanoTime() - start, yamlSource());
        } catch (SceneException e) {
            return TaskResult.failed(frame, e.getMessage(), yamlSource());
        } catch (IllegalStateException e) {
            // a mesh that could not be read after all, found while preparing
            if (e.getCause() instanceof SceneException cause) {
                return TaskResult.failed(frame, cause.getMessage(), yamlSource());
            }
            throw e;
        }
    }

    /** Renders frame {@code frame} whole and writes its file atomically. */
    private byte[] whole(int frame, Workers workers, TaskContext context, long[] sceneNanos, long start) throws Exception {
        Scene scene = ExecutorScenes.scene(job, sceneNanos);
        SceneFrame loaded = scene.load(frame, workers);
        String input = Outputs.whyInput(job.output(frame), loaded.report().inputs());
        if (input != null) {
            return TaskResult.failed(frame, input, yamlSource());
        }
        loaded.prepare(workers);
        ImageSettings image = loaded.image();
        Film film = new Film(image.width(), image.height());
        RenderStats stats = loaded.renderer(workers).render(film);
        String target = job.output(frame);
        Configuration conf = ExecutorScenes.hadoop();
        failIfHooked(context, target);
        long bytes = Outputs.write(target, job.runId, conf,
                                   out -> ImageWriters.encode(film, image.exposure(), image.srgb(), new org.apache.hadoop.fs.Path(target).getName(),
                                                              out));
        return TaskResult.written(frame, target, bytes, stats, sceneNanos[0], System.nanoTime() - start, yamlSource());
    }

    private void failIfHooked(TaskContext context, String target) throws Exception {
        if (context == null || context.attemptNumber() != 0) {
            return;
        }
        String hooked = context.getLocalProperty(FAIL_FIRST_ATTEMPT);
        if (hooked != null && Integer.parseInt(hooked) == context.partitionId()) {
            if (target != null) {
                Outputs.leavePartial(target, job.runId, ExecutorScenes.hadoop());
            }
            throw new IllegalStateException("the test hook fails the first attempt of task " + context.partitionId());
        }
    }

    /** Where this JVM's SnakeYAML comes from ("render.jar"), for the driver's report. */
    static String yamlSource() {
        return source(org.yaml.snakeyaml.LoaderOptions.class);
    }

    static String source(Class<?> type) {
        URL location = type.getProtectionDomain().getCodeSource() == null ? null : type.getProtectionDomain().getCodeSource().getLocation();
        if (location == null) {
            return "an unknown place";
        }
        String path = location.getPath();
        Path name = Path.of(path.endsWith("/") ? path.substring(0, path.length() - 1) : path).getFileName();
        return name == null ? path : name.toString();
    }
}

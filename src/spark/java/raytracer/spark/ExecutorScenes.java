package raytracer.spark;

import java.nio.file.Path;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import org.apache.hadoop.conf.Configuration;
import raytracer.api.Scene;
import raytracer.api.SceneFrame;
import raytracer.api.SceneOptions;
import raytracer.render.Workers;

/**
 * The scenes an executor JVM has read, kept for its later tasks: a lazily filled cache keyed by the
 * scene's digest, its path and the options ({@link Job#key}), so each executor reads a scene (and
 * its meshes, from the mesh cache when filled) once however many tasks it runs; and the frame a
 * still's tile runs share, prepared once. The one piece of static mutable state of the project,
 * on purpose: it lives as long as the executor JVM, which is what Spark gives a task to share.
 * Concurrent tasks asking for the same scene wait for the one load. A few entries only: past
 * {@link #KEPT} the least recently used is dropped (its meshes go when no task holds them).
 */
final class ExecutorScenes {
    static final int KEPT = 4;
    private static final Map<String, CompletableFuture<Scene>> SCENES = new LinkedHashMap<>(16, 0.75f, true);
    private static final Map<String, CompletableFuture<SceneFrame>> FRAMES = new LinkedHashMap<>(16, 0.75f, true);

    private static Configuration hadoop;

    private ExecutorScenes() {
    }

    /**
     * The executor's Hadoop configuration, made by the first task that writes a file: each new
     * Configuration parses Hadoop's XML defaults again, a cost every frame's task would pay. Reading
     * a Configuration from several threads is safe; no task changes it.
     */
    static synchronized Configuration hadoop() {
        if (hadoop == null) {
            hadoop = new Configuration();
        }
        return hadoop;
    }

    /** The job's scene, read on the first call in this JVM; {@code took[0]} gets the time the read took if this call read it. */
    static Scene scene(Job job, long[] took) throws Exception {
        return memo(SCENES, job.key, took, () -> {
            SceneOptions options = job.options;
            if (job.executorMeshCache) {
                // the executor's own default folder: the driver's home need not exist here
                options = options.withDefaultMeshCache();
            }
            return Scene.of(job.scenePath == null ? null : Path.of(job.scenePath), job.sceneText, options);
        });
    }

    /**
     * Frame {@code frame} of the job's scene, loaded and prepared on {@code workers} by the first
     * task that asks; the tile runs of a frame share it (a prepared world is read-only while rendering).
     */
    static SceneFrame prepared(Job job, int frame, Workers workers, long[] took) throws Exception {
        Scene scene = scene(job, took);
        return memo(FRAMES, job.key + "\nframe " + frame, new long[1], () -> {
            SceneFrame loaded = scene.load(frame, workers);
            loaded.prepare(workers);
            return loaded;
        });
    }

    /** Work that may fail, as a load does. */
    private interface Load<T> {
        T run() throws Exception;
    }

    /**
     * The value of {@code key} in {@code cache}, made by {@code load} once (the time it took in
     * {@code took[0]}, for the call that made it); a failed load is forgotten, so a retry loads again.
     */
    private static <T> T memo(Map<String, CompletableFuture<T>> cache, String key, long[] took, Load<T> load) throws Exception {
        CompletableFuture<T> future;
        boolean mine = false;
        synchronized (cache) {
            future = cache.get(key);
            if (future == null) {
                future = new CompletableFuture<>();
                cache.put(key, future);
                mine = true;
                Iterator<String> oldest = cache.keySet().iterator();
                while (cache.size() > KEPT) {
                    oldest.next();
                    oldest.remove();
                }
            }
        }
        if (mine) {
            long start = System.nanoTime();
            try {
                future.complete(load.run());
                took[0] = System.nanoTime() - start;
            } catch (Exception | Error e) {
                future.completeExceptionally(e);
                synchronized (cache) {
                    cache.remove(key, future);
                }
            }
        }
        try {
            return future.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Exception cause) {
                throw cause;
            }
            throw (Error) e.getCause();
        }
    }
}

package raytracer.spark;

import java.io.Serializable;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import raytracer.api.SceneOptions;

/**
 * What every task of one render needs, sent once with the tasks: the scene file's text (read on
 * the driver, so every executor renders the same scene) and the path by which executors find its
 * folder (meshes and images are read relative to it: a shared file system, or where --archives
 * unpacked them), the options, the threads per task, and the files of the frames that tasks write
 * whole. Plain values only, so any serializer Spark is given can carry it.
 */
final class Job implements Serializable {
    private static final long serialVersionUID = 1L;

    /** The scene file's text. */
    final String sceneText;
    /** The scene file's path on the executors; null for the embedded default scene. */
    final String scenePath;
    final SceneOptions options;
    /** True when no mesh cache was named: each executor uses its own default folder. */
    final boolean executorMeshCache;
    /** Worker threads per task; 0 for the task's cores ({@code spark.task.cpus}). */
    final int threads;
    /** Names the temporary files of this run (the application's id), which the driver removes at the end. */
    final String runId;
    /** The first frame of the range, and per frame from it, the file (a qualified URI) that a task rendering it whole writes. */
    final int firstFrame;
    final String[] outputs;
    /** The scene's digest with everything else that changes what an executor loads: its cache's key. */
    final String key;

    Job(String sceneText, String scenePath, SceneOptions options, boolean executorMeshCache, int threads, String runId, int firstFrame,
        String[] outputs) {
        this.sceneText = sceneText;
        this.scenePath = scenePath;
        this.options = options;
        this.executorMeshCache = executorMeshCache;
        this.threads = threads;
        this.runId = runId;
        this.firstFrame = firstFrame;
        this.outputs = outputs.clone();
        this.key = sha256(sceneText) + "\n" + scenePath + "\n" + options + "\n" + executorMeshCache;
    }

    /** The file of frame {@code frame}, for a task that renders it whole. */
    String output(int frame) {
        return outputs[frame - firstFrame];
    }

    static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}

package raytracer.cli;

import java.nio.file.Path;
import raytracer.accel.Aggregation;

/**
 * The command's options, checked and parsed: everything a {@link RenderRun} needs to know.
 *
 * @param scene the scene file, or null for the embedded default scene
 * @param output the image file, known to be writable; of an animation, the first frame's
 * @param frames the frames of the animation to render, or null for a still (frame 0)
 * @param framePattern the animation's file names, one {@code %d} for the frame number; null for a still
 * @param resume with frames: skip frames whose file is complete
 * @param costView true for --view bvh-cost
 * @param analyse false for --no-skip: the scene analysis does not run, so nothing is left out
 * @param meshCache the mesh cache's folder, or null for none (--no-cache)
 * @param meshCacheMax the bytes the mesh cache's entries may take together
 * @param show true for --show: a window shows the image as it renders (a display is known to be there)
 */
record RenderRequest(Path scene, Path output, SceneOverrides overrides, Aggregation.Mode accel, boolean costView, boolean analyse,
                     int threads, long seed, int repeat, boolean stats, boolean quiet, Path meshCache, long meshCacheMax, boolean show,
                     FrameRange frames, String framePattern, boolean resume) {

    /** The file of frame {@code frame}: the pattern's, or the still's output. */
    Path output(int frame) {
        return framePattern == null ? output : FrameFiles.name(framePattern, frame);
    }
}

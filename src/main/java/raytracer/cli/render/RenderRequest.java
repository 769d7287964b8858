package raytracer.cli.render;

import java.nio.file.Path;
import raytracer.api.FrameFiles;
import raytracer.api.FrameRange;
import raytracer.api.SceneOptions;

/**
 * The command's options, checked and parsed: everything a {@link RenderRun} needs to know.
 *
 * @param scene the scene file, or null for the embedded default scene
 * @param output the image file, known to be writable; of an animation, the first frame's (the
 * frames' files are checked by {@link FrameOutputs} once the scene is read)
 * @param options what changes the scene, and its search and mesh cache, as {@link raytracer.api.Scene} applies them
 * @param show true for --show: a window shows the image as it renders (a display is known to be there)
 * @param frames the frames of the animation to render, or null for a still (frame 0)
 * @param framePattern the animation's file names, one {@code %d} for the frame number; null for a still
 * @param resume with frames: skip frames whose file is complete
 */
public record RenderRequest(Path scene, Path output, SceneOptions options, int threads, int repeat, boolean stats, boolean quiet, boolean show,
                     FrameRange frames, String framePattern, boolean resume) {

    /** The file of frame {@code frame}: the pattern's, or the still's output. */
    public Path output(int frame) {
        return framePattern == null ? output : FrameFiles.name(framePattern, frame);
    }
}

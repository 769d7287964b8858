package raytracer.api;

/**
 * The frames {@code --frames} asks for: {@code A-B} (both included) or a single {@code A}, numbered
 * from 0 as the scene's animation numbers them.
 */
public record FrameRange(int first, int last) {

    /** The range of {@code text}, or IllegalArgumentException saying what was expected. */
    public static FrameRange parse(String text) {
        String[] ends = text.strip().split("-", -1);
        if (ends.length > 2 || !ends[0].matches("\\d{1,9}") || ends.length == 2 && !ends[1].matches("\\d{1,9}")) {
            throw new IllegalArgumentException("--frames must be FIRST-LAST or one frame number, such as 0-119 or 12, got '" + text + "'");
        }
        int first = Integer.parseInt(ends[0]);
        int last = ends.length == 2 ? Integer.parseInt(ends[1]) : first;
        if (last < first) {
            throw new IllegalArgumentException("--frames " + text + ": the last frame comes before the first");
        }
        return new FrameRange(first, last);
    }

    public int count() {
        return last - first + 1;
    }

    /** Why the range does not fit a scene of {@code frames} frames, or null when it does. */
    public String whyNotIn(int frames, boolean animated) {
        if (!animated) {
            return "the scene has no animation section (a still is frame 0)" + (first == 0 && last == 0 ? "" : "; drop --frames");
        }
        return last < frames ? null : "the scene's animation has " + frames + " frame" + (frames == 1 ? "" : "s") + ", 0 to "
                                        + (frames - 1) + "; --frames asked for " + first + "-" + last;
    }
}

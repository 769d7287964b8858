package raytracer.io.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.ScalarNode;

/**
 * The keys of an animated camera or object read into one {@link Track} per channel: each key at a
 * frame or a time in seconds, in order, giving some of the channels; each channel interpolated,
 * linearly or smoothly, through the keys that give it.
 */
final class KeyTracks {
    private KeyTracks() {
    }

    /** The tracks of a motion's {@code keys}: one per channel that some key gives, through the keys that give it. */
    static Map<String, Track> read(Source source, YamlObject motion, int frames, double fps, Set<String> channels,
                                             String what) throws SceneException {
        String interpolation = motion.string("interpolation", "linear");
        if (!interpolation.equals("linear") && !interpolation.equals("smooth")) {
            throw source.error(motion.raw("interpolation"), "unknown interpolation '" + interpolation + "'; allowed: linear, smooth");
        }
        List<Node> keys = motion.list("keys");
        if (keys.isEmpty()) {
            throw source.error(motion.raw("keys"), "'keys' must list at least one key such as {frame: 0, ...}");
        }
        Set<String> allowed = new java.util.HashSet<>(channels);
        allowed.add("frame");
        allowed.add("time");
        Map<String, List<double[]>> times = new LinkedHashMap<>();
        Map<String, List<double[]>> values = new LinkedHashMap<>();
        double previous = Double.NEGATIVE_INFINITY;
        for (Node keyNode : keys) {
            YamlObject key = new YamlObject(source, keyNode, what, allowed);
            if (key.has("frame") == key.has("time")) {
                throw source.error(keyNode, what + " needs either 'frame' (0 to " + (frames - 1) + ") or 'time' (seconds)");
            }
            double frame = key.has("frame") ? keyFrame(source, key) : keyTime(source, key, fps);
            if (!(frame > previous)) {
                throw source.error(key.has("frame") ? key.raw("frame") : key.raw("time"), "keys must be in order of time, "
                                   + "each after the one before");
            }
            previous = frame;
            for (String channel : channels) {
                if (key.has(channel)) {
                    times.computeIfAbsent(channel, k -> new ArrayList<>()).add(new double[] {frame});
                    values.computeIfAbsent(channel, k -> new ArrayList<>()).add(value(key, channel));
                }
            }
        }
        Map<String, Track> tracks = new LinkedHashMap<>();
        for (String channel : times.keySet()) {
            double[] t = times.get(channel).stream().mapToDouble(x -> x[0]).toArray();
            tracks.put(channel, new Track(t, values.get(channel).toArray(new double[0][]), interpolation.equals("smooth")));
        }
        return tracks;
    }

    /** A key's {@code frame}, within {@link Animation#MAX_KEY_FRAME} either way. */
    private static double keyFrame(Source source, YamlObject key) throws SceneException {
        double frame = key.requiredNumber("frame");
        if (Math.abs(frame) > Animation.MAX_KEY_FRAME) {
            throw source.error(key.raw("frame"), "'frame' in " + key.what() + " must be " + YamlScalars.format(-Animation.MAX_KEY_FRAME) + " to "
                               + YamlScalars.format(Animation.MAX_KEY_FRAME) + ", got " + YamlScalars.format(frame));
        }
        return frame;
    }

    /** The frame of a key's {@code time} in seconds at {@code fps}: time x fps, within {@link Animation#MAX_KEY_FRAME} either way. */
    private static double keyTime(Source source, YamlObject key, double fps) throws SceneException {
        double time = key.requiredNumber("time");
        if (!(Math.abs(time * fps) <= Animation.MAX_KEY_FRAME)) {
            String most = seconds(Animation.MAX_KEY_FRAME / fps);
            throw source.error(key.raw("time"), "'time' in " + key.what() + " must be -" + most + " to " + most + " seconds at "
                               + YamlScalars.format(fps) + " fps (frames " + YamlScalars.format(-Animation.MAX_KEY_FRAME) + " to "
                               + YamlScalars.format(Animation.MAX_KEY_FRAME) + "), got " + YamlScalars.format(time));
        }
        return time * fps;
    }

    /**
     * A bound in seconds (at least 2147: fps is at most {@link Animation#MAX_FPS}) to the hundredth, rounded
     * towards zero, so that a time within the bound printed is allowed.
     */
    private static String seconds(double s) {
        return String.format(java.util.Locale.ROOT, "%.2f", Math.floor(s * 100) / 100);
    }

    /** A channel's value at a key: a triple, or a number; a scale may be either (a number scales evenly). */
    private static double[] value(YamlObject key, String channel) throws SceneException {
        return switch (channel) {
            case "eye", "look-at", "up", "translate" -> key.triple(channel, null);
            case "scale" -> {
                if (key.raw(channel) instanceof ScalarNode) {
                    double s = key.requiredNumber(channel);
                    yield new double[] {s, s, s};
                }
                yield key.triple(channel, null);
            }
            default -> new double[] {key.requiredNumber(channel)};
        };
    }
}

package raytracer.io.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.yaml.snakeyaml.DumperOptions;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.SequenceNode;
import org.yaml.snakeyaml.nodes.Tag;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;

/**
 * A scene's {@code animation} section: how many frames and at what rate; the camera's eye,
 * look-at, up and field of view as keyframes, or an orbit of the eye around a point; and keyframed
 * transforms of named objects. Frames are numbered from 0; a key is placed by {@code frame} or by
 * {@code time} in seconds (frame = time x fps). Format: docs/scene-format.md.
 */
final class Animation {
    static final int MAX_FRAMES = 1_000_000;
    static final double DEFAULT_FPS = 24;
    /**
     * The rates allowed: a frame every million seconds of the scene's time (11.6 days: a time-lapse
     * of years) to a million frames a second. Far outside them a key's time x fps overflows to an
     * infinite frame or, near the smallest doubles, stops telling keys apart.
     */
    static final double MIN_FPS = 1e-6;
    static final double MAX_FPS = 1e6;
    /**
     * The farthest frame a key may be at, either way: keys may lie outside the frames, but a frame
     * number fits an int; past it the span between two keys can overflow to infinity, which makes
     * every value between them NaN.
     */
    static final double MAX_KEY_FRAME = Integer.MAX_VALUE;
    /**
     * The largest sweep of an orbit either way: a turn a frame over the longest animation. Far past
     * it a frame's angle, degrees x frame / frames, loses its precision (at 1e20 degrees a double
     * steps by 16384 of them), and at 1e308 it overflows, which made the eye NaN.
     */
    static final double MAX_ORBIT_DEGREES = 360.0 * MAX_FRAMES;
    private static final Set<String> KEYS = Set.of("frames", "fps", "camera", "objects");
    private static final Set<String> CAMERA_CHANNELS = Set.of("eye", "look-at", "up", "fov");
    private static final Set<String> OBJECT_CHANNELS = Set.of("translate", "rotate-x", "rotate-y", "rotate-z", "scale");

    private final int frames;
    private final double fps;
    private final Node cameraNode;
    /** Per camera channel that some key gives, its track; empty for an orbit or no camera motion. */
    private final Map<String, Track> camera;
    /** The orbit's centre (null: around the camera's look-at) and sweep in degrees, or null for keys. */
    private final Point3D orbitCenter;
    /** The node of the orbit's centre (or of the orbit), for a message about the eye it turns. */
    private final Node orbitNode;
    private final double orbitDegrees;
    private final boolean orbit;
    /** Per object name, its channels' tracks, and the node of its motion for messages. */
    private final Map<String, Map<String, Track>> objects;
    private final Map<String, Node> objectNodes;

    private Animation(int frames, double fps, Node cameraNode, Map<String, Track> camera, boolean orbit, Point3D orbitCenter,
                      Node orbitNode, double orbitDegrees, Map<String, Map<String, Track>> objects, Map<String, Node> objectNodes) {
        this.frames = frames;
        this.fps = fps;
        this.cameraNode = cameraNode;
        this.camera = camera;
        this.orbit = orbit;
        this.orbitCenter = orbitCenter;
        this.orbitNode = orbitNode;
        this.orbitDegrees = orbitDegrees;
        this.objects = objects;
        this.objectNodes = objectNodes;
    }

    int frames() {
        return frames;
    }

    double fps() {
        return fps;
    }

    /** The names of the objects the animation moves, for checking them against the objects list. */
    Map<String, Node> objectNodes() {
        return objectNodes;
    }

    /**
     * The camera section of frame {@code frame}: the file's ({@code base}; null when it has none)
     * with the animated eye, look-at, up and field of view in place of its own, as YAML nodes
     * placed at the animation's camera for messages. {@link CameraReader} reads it as it reads the
     * file's, so a frame's camera is made, and checked, as a still's is.
     */
    Node camera(Source source, Node base, int frame) throws SceneException {
        List<NodeTuple> tuples = new ArrayList<>();
        if (base instanceof MappingNode mapping) {
            tuples.addAll(mapping.getValue());
        }
        if (!orbit && camera.isEmpty()) {
            return base;
        }
        YamlObject file = base == null ? null : new YamlObject(source, base, "camera", AnyName.INSTANCE);
        Point3D eye = file == null ? CameraReader.DEFAULT_EYE : file.point("eye", CameraReader.DEFAULT_EYE);
        Point3D lookAt = file == null ? CameraReader.DEFAULT_LOOK_AT : file.point("look-at", CameraReader.DEFAULT_LOOK_AT);
        Map<String, double[]> values = new LinkedHashMap<>();
        if (orbit) {
            // the eye turned about the vertical axis through the centre by the sweep's share of this frame
            Point3D center = orbitCenter != null ? orbitCenter : lookAt;
            Point3D turned = Matrix4.translate(center.x(), center.y(), center.z())
                .multiply(Matrix4.rotateY(orbitDegrees * frame / frames))
                .multiply(Matrix4.translate(-center.x(), -center.y(), -center.z())).transform(eye);
            if (!(Double.isFinite(turned.x()) && Double.isFinite(turned.y()) && Double.isFinite(turned.z()))) {
                throw source.error(orbitNode, "the orbit turns the eye past the largest double at frame " + frame + ": the eye "
                                   + eye + " and the centre " + center + " must lie nearer each other and the origin");
            }
            values.put("eye", new double[] {turned.x(), turned.y(), turned.z()});
        }
        camera.forEach((channel, track) -> values.put(channel, track.at(frame)));
        tuples.removeIf(t -> t.getKeyNode() instanceof ScalarNode key && values.containsKey(key.getValue()));
        Mark start = cameraNode.getStartMark();
        Mark end = cameraNode.getEndMark();
        for (Map.Entry<String, double[]> value : values.entrySet()) {
            List<Node> numbers = new ArrayList<>();
            for (double v : value.getValue()) {
                numbers.add(new ScalarNode(Tag.FLOAT, Double.toString(v), start, end, DumperOptions.ScalarStyle.PLAIN));
            }
            Node node = numbers.size() == 1 ? numbers.get(0)
                : new SequenceNode(Tag.SEQ, true, numbers, start, end, DumperOptions.FlowStyle.FLOW);
            tuples.add(new NodeTuple(new ScalarNode(Tag.STR, value.getKey(), start, end, DumperOptions.ScalarStyle.PLAIN), node));
        }
        return new MappingNode(Tag.MAP, true, tuples, start, end, DumperOptions.FlowStyle.FLOW);
    }

    /**
     * The motion of object {@code name} at {@code frame}, applied after the object's own transform:
     * scale, rotate-x, rotate-y, rotate-z, translate, in that order (as a transform list of those
     * steps); null when the animation does not move the object.
     */
    Matrix4 transform(String name, int frame) {
        Map<String, Track> tracks = name == null ? null : objects.get(name);
        if (tracks == null) {
            return null;
        }
        double[] s = tracks.containsKey("scale") ? tracks.get("scale").at(frame) : new double[] {1, 1, 1};
        double[] t = tracks.containsKey("translate") ? tracks.get("translate").at(frame) : new double[] {0, 0, 0};
        Matrix4 m = Matrix4.scale(s[0], s[1], s[2]);
        for (String axis : List.of("rotate-x", "rotate-y", "rotate-z")) {
            if (tracks.containsKey(axis)) {
                double degrees = tracks.get(axis).at(frame)[0];
                m = (axis.equals("rotate-x") ? Matrix4.rotateX(degrees) : axis.equals("rotate-y") ? Matrix4.rotateY(degrees)
                     : Matrix4.rotateZ(degrees)).multiply(m);
            }
        }
        return Matrix4.translate(t[0], t[1], t[2]).multiply(m);
    }

    /** Reads the section; {@code orthographic} says whether the file's camera has no field of view. */
    static Animation read(Source source, Node node, boolean orthographic) throws SceneException {
        YamlObject a = new YamlObject(source, node, "animation", KEYS);
        int frames = a.integer("frames", 0, 1, MAX_FRAMES);
        if (!a.has("frames")) {
            throw source.error(node, "animation needs the key 'frames' (how many frames, numbered from 0)");
        }
        double fps = a.number("fps", DEFAULT_FPS, 0, true);
        if (fps < MIN_FPS || fps > MAX_FPS) {
            throw source.error(a.raw("fps"), "'fps' in animation must be " + YamlScalars.format(MIN_FPS) + " to "
                               + YamlScalars.format(MAX_FPS) + " (frames a second of the scene's time), got " + YamlScalars.format(fps));
        }
        Map<String, Track> camera = new LinkedHashMap<>();
        boolean orbit = false;
        Point3D center = null;
        Node orbitNode = null;
        double degrees = 360;
        if (a.has("camera")) {
            YamlObject c = new YamlObject(source, a.raw("camera"), "the animation's camera", Set.of("keys", "interpolation", "orbit"));
            if (c.has("orbit") == c.has("keys")) {
                throw source.error(a.raw("camera"), "the animation's camera needs either 'keys' or 'orbit'");
            }
            if (c.has("orbit")) {
                if (c.has("interpolation")) {
                    throw source.error(c.raw("interpolation"), "'interpolation' is for keys; an orbit turns at an even rate");
                }
                YamlObject o = new YamlObject(source, c.raw("orbit"), "orbit", Set.of("center", "degrees"));
                orbit = true;
                center = o.point("center", null);
                orbitNode = o.has("center") ? o.raw("center") : c.raw("orbit");
                degrees = o.number("degrees", 360);
                if (Math.abs(degrees) > MAX_ORBIT_DEGREES) {
                    throw source.error(o.raw("degrees"), "'degrees' in orbit must be " + YamlScalars.format(-MAX_ORBIT_DEGREES) + " to "
                                       + YamlScalars.format(MAX_ORBIT_DEGREES) + " (a turn a frame over " + MAX_FRAMES
                                       + " frames, the most an animation has), got " + YamlScalars.format(degrees));
                }
            } else {
                camera = KeyTracks.read(source, c, frames, fps, CAMERA_CHANNELS, "camera key");
                if (orthographic && camera.containsKey("fov")) {
                    throw source.error(c.raw("keys"), "an orthographic camera has no 'fov' to animate");
                }
            }
        }
        Map<String, Map<String, Track>> objects = new LinkedHashMap<>();
        Map<String, Node> objectNodes = new LinkedHashMap<>();
        if (a.has("objects")) {
            YamlObject names = new YamlObject(source, a.raw("objects"), "the animation's objects", AnyName.INSTANCE);
            for (Map.Entry<String, Node> entry : names.keyNodes().entrySet()) {
                String name = entry.getKey();
                YamlObject motion = new YamlObject(source, names.raw(name), "motion of object '" + name + "'",
                                                   Set.of("keys", "interpolation"));
                if (!motion.has("keys")) {
                    throw source.error(names.raw(name), "motion of object '" + name + "' needs the key 'keys'");
                }
                objects.put(name, KeyTracks.read(source, motion, frames, fps, OBJECT_CHANNELS, "key of object '" + name + "'"));
                objectNodes.put(name, entry.getValue());
            }
        }
        return new Animation(frames, fps, a.has("camera") ? a.raw("camera") : node, camera, orbit, center, orbitNode, degrees,
                             objects, objectNodes);
    }
}

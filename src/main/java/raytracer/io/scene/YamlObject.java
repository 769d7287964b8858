package raytracer.io.scene;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.SequenceNode;
import org.yaml.snakeyaml.nodes.Tag;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * One mapping of the scene file with typed, checked access. Construction rejects keys outside the
 * allowed set and duplicate keys; every getter says what was expected where, so the user never
 * sees a stack trace or a vague "bad value".
 */
final class YamlObject {
    private final Source source;
    private final Node node;
    private final String what;
    private final Map<String, Node> values = new LinkedHashMap<>();
    private final Map<String, Node> keys = new LinkedHashMap<>();

    YamlObject(Source source, Node node, String what, Collection<String> allowed) throws SceneException {
        if (!(node instanceof MappingNode mapping)) {
            throw source.error(node, what + " must be a mapping of keys to values, got " + YamlScalars.describe(node));
        }
        this.source = source;
        this.node = node;
        this.what = what;
        for (NodeTuple tuple : mapping.getValue()) {
            if (!(tuple.getKeyNode() instanceof ScalarNode keyNode)) {
                throw source.error(tuple.getKeyNode(), "keys in " + what + " must be plain names");
            }
            String key = keyNode.getValue();
            if (!allowed.contains(key)) {
                throw source.error(keyNode, "unknown key '" + key + "' in " + what + "; allowed: "
                                   + String.join(", ", new TreeSet<>(allowed)));
            }
            if (values.containsKey(key)) {
                throw source.error(keyNode, "duplicate key '" + key + "' in " + what);
            }
            values.put(key, tuple.getValueNode());
            keys.put(key, keyNode);
        }
    }

    /**
     * The {@code type} of a mapping, read before its keys are checked so that an unknown key can be
     * reported against the keys of that type; {@code fallback} when absent.
     */
    static String peekType(Source source, Node node, String what, String fallback) throws SceneException {
        if (!(node instanceof MappingNode mapping)) {
            throw source.error(node, what + " must be a mapping of keys to values, got " + YamlScalars.describe(node));
        }
        for (NodeTuple tuple : mapping.getValue()) {
            if (tuple.getKeyNode() instanceof ScalarNode key && key.getValue().equals("type")) {
                if (!(tuple.getValueNode() instanceof ScalarNode value) || value.getTag().equals(Tag.NULL)) {
                    throw source.error(tuple.getValueNode(), "'type' of " + what + " must be a name, got "
                                       + YamlScalars.describe(tuple.getValueNode()));
                }
                return value.getValue();
            }
        }
        if (fallback == null) {
            throw source.error(node, what + " needs the key 'type'");
        }
        return fallback;
    }

    /** The node holding the value of {@code type}, for messages about it. */
    static Node typeNode(Node node) {
        for (NodeTuple tuple : ((MappingNode) node).getValue()) {
            if (tuple.getKeyNode() instanceof ScalarNode key && key.getValue().equals("type")) {
                return tuple.getValueNode();
            }
        }
        return node;
    }

    Source source() {
        return source;
    }

    Node node() {
        return node;
    }

    String what() {
        return what;
    }

    boolean has(String key) {
        return values.containsKey(key);
    }

    /** The value node of a key, or null. */
    Node raw(String key) {
        return values.get(key);
    }

    /** The value node of a key that must be present. */
    Node required(String key) throws SceneException {
        Node value = values.get(key);
        if (value == null) {
            throw source.error(node, what + " needs the key '" + key + "'");
        }
        return value;
    }

    String string(String key, String fallback) throws SceneException {
        Node value = values.get(key);
        return value == null ? fallback : scalarText(value, key);
    }

    /** An error at {@code key}'s value, or at this mapping when the key is absent. */
    SceneException error(String key, String message) {
        return source.error(values.containsKey(key) ? values.get(key) : node, message);
    }

    /** A value that must be one of {@code allowed}; {@code fallback} when the key is absent. */
    String choice(String key, String fallback, java.util.List<String> allowed) throws SceneException {
        String value = string(key, fallback);
        if (!allowed.contains(value)) {
            throw source.error(values.get(key), "'" + key + "' in " + what + " must be one of " + String.join(", ", allowed) + ", got '" + value + "'");
        }
        return value;
    }

    String requiredString(String key) throws SceneException {
        return scalarText(required(key), key);
    }

    private String scalarText(Node value, String key) throws SceneException {
        if (!(value instanceof ScalarNode scalar) || scalar.getTag().equals(Tag.NULL)) {
            throw source.error(value, "'" + key + "' in " + what + " must be a single value, got " + YamlScalars.describe(value));
        }
        return scalar.getValue();
    }

    double number(String key, double fallback) throws SceneException {
        Node value = values.get(key);
        return value == null ? fallback : YamlScalars.number(source, value, "'" + key + "' in " + what);
    }

    double requiredNumber(String key) throws SceneException {
        return YamlScalars.number(source, required(key), "'" + key + "' in " + what);
    }

    /** A number that must be at least {@code min} (or above it, when {@code strict}). */
    double number(String key, double fallback, double min, boolean strict) throws SceneException {
        double v = has(key) ? requiredNumber(key) : fallback;
        if (strict ? !(v > min) : !(v >= min)) {
            throw source.error(has(key) ? raw(key) : node, "'" + key + "' in " + what + " must be "
                               + (strict ? "greater than " : "at least ") + YamlScalars.format(min) + ", got " + YamlScalars.format(v));
        }
        return v;
    }

    int integer(String key, int fallback, int min) throws SceneException {
        return integer(key, fallback, min, Integer.MAX_VALUE);
    }

    /** A whole number from {@code min} to {@code max}. */
    int integer(String key, int fallback, int min, int max) throws SceneException {
        if (!has(key)) {
            return fallback;
        }
        double v = requiredNumber(key);
        if (v != Math.rint(v)) {
            throw source.error(raw(key), "'" + key + "' in " + what + " must be a whole number, got " + YamlScalars.format(v));
        }
        if (v < min) {
            throw source.error(raw(key), "'" + key + "' in " + what + " must be at least " + min + ", got " + YamlScalars.format(v));
        }
        if (v > max) {
            throw source.error(raw(key), "'" + key + "' in " + what + " must be at most " + max + ", got " + YamlScalars.format(v));
        }
        return (int) v;
    }

    boolean bool(String key, boolean fallback) throws SceneException {
        Node value = values.get(key);
        if (value == null) {
            return fallback;
        }
        if (value instanceof ScalarNode scalar && scalar.getTag().equals(Tag.BOOL)) {
            return Boolean.parseBoolean(scalar.getValue().toLowerCase(java.util.Locale.ROOT))
                   || scalar.getValue().equalsIgnoreCase("yes") || scalar.getValue().equalsIgnoreCase("on");
        }
        throw source.error(value, "'" + key + "' in " + what + " must be true or false, got " + YamlScalars.describe(value));
    }

    double[] triple(String key, double[] fallback) throws SceneException {
        Node value = values.get(key);
        return value == null ? fallback : YamlScalars.triple(source, value, "'" + key + "' in " + what);
    }

    Point3D point(String key, Point3D fallback) throws SceneException {
        if (!has(key)) {
            return fallback;
        }
        double[] t = triple(key, null);
        return new Point3D(t[0], t[1], t[2]);
    }

    Point3D requiredPoint(String key) throws SceneException {
        double[] t = YamlScalars.triple(source, required(key), "'" + key + "' in " + what);
        return new Point3D(t[0], t[1], t[2]);
    }

    Vector3D requiredVector(String key) throws SceneException {
        double[] t = YamlScalars.triple(source, required(key), "'" + key + "' in " + what);
        return new Vector3D(t[0], t[1], t[2]);
    }

    Vector3D vector(String key, Vector3D fallback) throws SceneException {
        if (!has(key)) {
            return fallback;
        }
        double[] t = triple(key, null);
        return new Vector3D(t[0], t[1], t[2]);
    }

    /** A linear RGB colour with non-negative components. */
    RGBColor color(String key, RGBColor fallback) throws SceneException {
        if (!has(key)) {
            return fallback;
        }
        double[] t = triple(key, null);
        if (t[0] < 0 || t[1] < 0 || t[2] < 0) {
            throw source.error(raw(key), "'" + key + "' in " + what + " must have no negative component");
        }
        return new RGBColor(t[0], t[1], t[2]);
    }

    /**
     * Checks what a light emits: {@code scale} (the value of {@code scaleKey}) times {@code factor},
     * the brightest channel of its colour ({@code factorName}, read from {@code factorKey}). Above the
     * largest float the image could only hold infinity. The message points at the scale if given,
     * else at the factor's key, else at this mapping.
     */
    void checkEmission(String scaleKey, double scale, String factorKey, String factorName, double factor)
            throws SceneException {
        if (!(scale * factor <= MAX_EMISSION)) {
            Node where = has(scaleKey) ? raw(scaleKey) : has(factorKey) ? raw(factorKey) : node;
            throw source.error(where, String.format(java.util.Locale.ROOT, "'%s' x %s in %s must be at most %.6g "
                                                    + "(the largest value an image holds), got %.6g x %.6g",
                                                    scaleKey, factorName, what, MAX_EMISSION, scale, factor));
        }
    }

    /** Checks {@code scale} times the colour of {@code colorKey}. */
    void checkEmission(String scaleKey, double scale, String colorKey, RGBColor color) throws SceneException {
        checkEmission(scaleKey, scale, colorKey, "'" + colorKey + "'", color.max());
    }

    /** The most a light may emit in one channel: the image holds floats. */
    static final double MAX_EMISSION = Float.MAX_VALUE;

    List<Node> list(String key) throws SceneException {
        Node value = values.get(key);
        if (value == null) {
            return List.of();
        }
        if (!(value instanceof SequenceNode sequence)) {
            throw source.error(value, "'" + key + "' in " + what + " must be a list, got " + YamlScalars.describe(value));
        }
        return new ArrayList<>(sequence.getValue());
    }

    /** Keys in file order with their key nodes (for maps of names, such as materials). */
    Map<String, Node> keyNodes() {
        return keys;
    }

    /** A file named by {@code key}, resolved against the scene's folder; a name that is no path is an error at it. */
    java.nio.file.Path path(String key) throws SceneException {
        String name = requiredString(key);
        try {
            return source.resolve(name);
        } catch (java.nio.file.InvalidPathException e) {
            throw source.error(raw(key), "'" + key + "' in " + what + " is not a valid path (" + e.getReason() + "): '"
                                         + name + "'");
        }
    }

}

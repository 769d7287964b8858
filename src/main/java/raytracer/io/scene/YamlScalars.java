package raytracer.io.scene;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.SequenceNode;
import org.yaml.snakeyaml.nodes.Tag;

/**
 * The scene file's values as messages need them: a number or a triple read from a YAML node with
 * the error at its place when it is not one, a node described for a message, numbers and lists of
 * names written back as a person wrote them.
 */
final class YamlScalars {
    private YamlScalars() {
    }

    static double number(Source source, Node value, String what) throws SceneException {
        if (!(value instanceof ScalarNode scalar)
            || !(scalar.getTag().equals(Tag.INT) || scalar.getTag().equals(Tag.FLOAT))) {
            throw source.error(value, what + " must be a number, got " + describe(value));
        }
        String text = scalar.getValue().toLowerCase(java.util.Locale.ROOT);
        if (text.endsWith(".nan") || text.endsWith(".inf")) {
            throw source.error(value, what + " must be a finite number, got '" + scalar.getValue() + "'");
        }
        double v;
        try {
            v = Double.parseDouble(scalar.getValue().replace("_", ""));
        } catch (NumberFormatException e) {
            throw source.error(value, what + " must be a plain decimal number, got '" + scalar.getValue() + "'");
        }
        if (!Double.isFinite(v)) {
            throw source.error(value, what + " must be a finite number, got '" + scalar.getValue() + "'");
        }
        return v;
    }

    static double[] triple(Source source, Node value, String what) throws SceneException {
        if (!(value instanceof SequenceNode sequence) || sequence.getValue().size() != 3) {
            throw source.error(value, what + " must be a list of 3 numbers [x, y, z], got " + describe(value));
        }
        double[] t = new double[3];
        for (int i = 0; i < 3; i++) {
            t[i] = number(source, sequence.getValue().get(i), what);
        }
        return t;
    }

    static String describe(Node value) {
        if (value instanceof ScalarNode scalar) {
            return scalar.getTag().equals(Tag.NULL) ? "nothing" : "'" + scalar.getValue() + "'";
        }
        if (value instanceof SequenceNode sequence) {
            return "a list of " + sequence.getValue().size();
        }
        return "a mapping";
    }

    /** The most names a message lists; the rest are counted. */
    static final int NAMES_LISTED = 10;

    /**
     * Names for a message, sorted: all of them, or the first {@value #NAMES_LISTED} and how many
     * more (200,000 materials would otherwise make a line of 1.7 MB).
     */
    static String names(java.util.Collection<String> names) {
        List<String> sorted = new ArrayList<>(new TreeSet<>(names));
        if (sorted.size() <= NAMES_LISTED) {
            return String.join(", ", sorted);
        }
        return String.join(", ", sorted.subList(0, NAMES_LISTED)) + String.format(java.util.Locale.ROOT, " and %,d more",
                                                                                 sorted.size() - NAMES_LISTED);
    }

    static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}

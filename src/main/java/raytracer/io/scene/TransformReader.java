package raytracer.io.scene;

import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.SequenceNode;
import raytracer.math.Matrix4;

/**
 * A {@code transform} list: scale, rotate-x/y/z (degrees), translate and matrix steps, applied in
 * list order, so the first step acts on the object first (M = S_n ... S_2 S_1).
 */
final class TransformReader {
    private static final Set<String> STEPS = Set.of("scale", "rotate-x", "rotate-y", "rotate-z", "translate", "matrix");

    private TransformReader() {
    }

    static Matrix4 read(Source source, Node node) throws SceneException {
        if (!(node instanceof SequenceNode list)) {
            throw source.error(node, "'transform' must be a list of steps such as {translate: [x, y, z]}");
        }
        Matrix4 m = Matrix4.IDENTITY;
        for (Node stepNode : list.getValue()) {
            YamlObject step = new YamlObject(source, stepNode, "transform step", STEPS);
            if (step.keyNodes().size() != 1) {
                throw source.error(stepNode, "each transform step has exactly one key, e.g. {rotate-y: 30}");
            }
            String kind = step.keyNodes().keySet().iterator().next();
            m = step(source, step, kind).multiply(m);
        }
        return checked(source, node, m, "");
    }

    /**
     * {@code m}, or the error at {@code node} of a transform that overflows or is singular;
     * {@code when} ends the message's subject (" at frame 12" for an animated one).
     */
    static Matrix4 checked(Source source, Node node, Matrix4 m, String when) throws SceneException {
        double det = m.determinant3x3();
        if (!Double.isFinite(det) || !finite(m)) {
            throw source.error(node, "the transform" + when + " overflows: its determinant is " + det + " (scales, matrix entries or their "
                                     + "products past 1.8e308, the largest double)");
        }
        if (det == 0) {
            throw source.error(node, "the transform" + when + " is singular (a zero scale?)");
        }
        if (!finite(m.inverse())) {
            throw source.error(node, "the transform's inverse" + when + " overflows: its determinant " + det + " is too close to 0 "
                                     + "(a scale near 0?)");
        }
        return m;
    }

    private static boolean finite(Matrix4 m) {
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                if (!Double.isFinite(m.get(i, j))) {
                    return false;
                }
            }
        }
        return true;
    }

    private static Matrix4 step(Source source, YamlObject step, String kind) throws SceneException {
        Node value = step.raw(kind);
        return switch (kind) {
            case "scale" -> {
                if (value instanceof ScalarNode) {
                    double s = step.number(kind, 1);
                    yield Matrix4.scale(s, s, s);
                }
                double[] s = step.triple(kind, null);
                yield Matrix4.scale(s[0], s[1], s[2]);
            }
            case "rotate-x" -> Matrix4.rotateX(step.number(kind, 0));
            case "rotate-y" -> Matrix4.rotateY(step.number(kind, 0));
            case "rotate-z" -> Matrix4.rotateZ(step.number(kind, 0));
            case "translate" -> {
                double[] t = step.triple(kind, null);
                yield Matrix4.translate(t[0], t[1], t[2]);
            }
            default -> matrix(source, value);
        };
    }

    private static Matrix4 matrix(Source source, Node value) throws SceneException {
        if (!(value instanceof SequenceNode seq) || seq.getValue().size() != 16) {
            throw source.error(value, "'matrix' must list 16 numbers, row by row");
        }
        double[] m = new double[16];
        for (int i = 0; i < 16; i++) {
            m[i] = YamlScalars.number(source, seq.getValue().get(i), "matrix entry " + (i + 1));
        }
        if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
            throw source.error(value, "'matrix' must be affine: its last row must be 0, 0, 0, 1");
        }
        return Matrix4.of(m);
    }
}

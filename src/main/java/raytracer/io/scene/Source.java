package raytracer.io.scene;

import java.nio.file.Path;
import org.yaml.snakeyaml.error.Mark;
import org.yaml.snakeyaml.nodes.Node;

/** The file being read: its name for messages and its folder for relative paths (meshes, textures). */
record Source(String name, Path folder) {

    /** "file:line:column: message", with 1-based line and column. */
    SceneException error(Node node, String message) {
        return error(node.getStartMark(), message);
    }

    SceneException error(Mark mark, String message) {
        return new SceneException(at(mark) + ": " + message);
    }

    /** "file:line:column" of a node, for warnings. */
    String at(Node node) {
        return at(node.getStartMark());
    }

    private String at(Mark mark) {
        return name + ":" + (mark.getLine() + 1) + ":" + (mark.getColumn() + 1);
    }

    Path resolve(String path) {
        Path p = Path.of(path);
        return p.isAbsolute() || folder == null ? p : folder.resolve(p).normalize();
    }
}

package raytracer.io.scene;

import java.util.HashSet;
import java.util.Set;
import java.util.TreeSet;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Plugin;
import raytracer.core.Plugins;

/** The registered type an entry's {@code type} names, and the keys the entry may have. */
final class RegisteredType {
    private RegisteredType() {
    }

    /** The type named {@code kind}, or an error at {@code node}'s type listing the registered names, sorted. */
    static <F> Plugin<F> find(Plugins<F> family, String what, String kind, Source source, Node node) throws SceneException {
        return family.find(kind).orElseThrow(() -> source.error(YamlObject.typeNode(node), "unknown " + what + " type '" + kind
                                                                + "'; allowed: " + String.join(", ", new TreeSet<>(family.names()))));
    }

    /** The keys of the family's every member and the type's own. */
    static Set<String> keys(Set<String> common, Plugin<?> type) {
        Set<String> all = new HashSet<>(common);
        all.addAll(type.keys());
        return all;
    }
}

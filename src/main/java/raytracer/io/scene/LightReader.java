package raytracer.io.scene;

import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Light;
import raytracer.lights.Directional;
import raytracer.lights.PointLight;
import raytracer.math.RGBColor;

/** One entry of the {@code lights} list: point or directional. */
final class LightReader {
    private LightReader() {
    }

    static Light read(Source source, Node node) throws SceneException {
        String kind = YamlObject.peekType(source, node, "light", null);
        YamlObject common = null;
        Light light = switch (kind) {
            case "point" -> {
                YamlObject l = new YamlObject(source, node, "point light", Set.of("type", "position", "intensity", "color", "shadows"));
                common = l;
                yield new PointLight(l.number("intensity", 1, 0, false), l.color("color", RGBColor.WHITE),
                                     l.requiredPoint("position"));
            }
            case "directional" -> {
                YamlObject l = new YamlObject(source, node, "directional light", Set.of("type", "direction", "radiance", "color", "shadows"));
                common = l;
                try {
                    yield new Directional(l.number("radiance", 1, 0, false), l.color("color", RGBColor.WHITE),
                                          l.requiredVector("direction"));
                } catch (IllegalArgumentException e) {
                    throw source.error(l.raw("direction"), e.getMessage());
                }
            }
            default -> throw source.error(YamlObject.typeNode(node), "unknown light type '" + kind + "'; allowed: directional, point");
        };
        light.setCastsShadows(common.bool("shadows", true));
        return light;
    }
}

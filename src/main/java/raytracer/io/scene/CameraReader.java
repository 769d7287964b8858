package raytracer.io.scene;

import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.cameras.Orthographic;
import raytracer.cameras.Pinhole;
import raytracer.cameras.ThinLens;
import raytracer.core.Camera;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/** The {@code camera} section: pinhole, thin-lens or orthographic. */
final class CameraReader {
    static final Point3D DEFAULT_EYE = new Point3D(0, 1, 6);
    static final Point3D DEFAULT_LOOK_AT = new Point3D(0, 0.5, 0);
    static final double DEFAULT_FOV = 45;
    static final double DEFAULT_VIEW_HEIGHT = 4;

    private CameraReader() {
    }

    static Camera defaultCamera() {
        return new Pinhole(DEFAULT_EYE, DEFAULT_LOOK_AT, Vector3D.UP, DEFAULT_FOV);
    }

    static Camera read(Source source, Node node) throws SceneException {
        String kind = YamlObject.peekType(source, node, "camera", "pinhole");
        Set<String> allowed = switch (kind) {
            case "pinhole" -> Set.of("type", "eye", "look-at", "up", "fov");
            case "thin-lens" -> Set.of("type", "eye", "look-at", "up", "fov", "lens-radius", "focal-distance");
            case "orthographic" -> Set.of("type", "eye", "look-at", "up", "view-height");
            default -> throw source.error(YamlObject.typeNode(node),
                "unknown camera type '" + kind + "'; allowed: orthographic, pinhole, thin-lens");
        };
        YamlObject c = new YamlObject(source, node, kind + " camera", allowed);
        Point3D eye = c.point("eye", DEFAULT_EYE);
        Point3D lookAt = c.point("look-at", DEFAULT_LOOK_AT);
        Vector3D up = c.vector("up", Vector3D.UP);
        try {
            return switch (kind) {
                case "pinhole" -> new Pinhole(eye, lookAt, up, c.number("fov", DEFAULT_FOV));
                case "thin-lens" -> new ThinLens(eye, lookAt, up, c.number("fov", DEFAULT_FOV),
                    c.number("lens-radius", 0.05), c.number("focal-distance", eye.distance(lookAt)));
                default -> new Orthographic(eye, lookAt, up, c.number("view-height", DEFAULT_VIEW_HEIGHT));
            };
        } catch (IllegalArgumentException e) {
            throw source.error(node, e.getMessage());
        }
    }
}

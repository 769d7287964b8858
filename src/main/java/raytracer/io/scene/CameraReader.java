package raytracer.io.scene;

import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.cameras.Orthographic;
import raytracer.cameras.Pinhole;
import raytracer.cameras.ThinLens;
import raytracer.core.Camera;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * The {@code camera} section: pinhole, thin-lens or orthographic. Read into a {@link Spec}, which
 * an animation varies frame by frame (eye, look-at, up, field of view) before the camera is made.
 */
final class CameraReader {
    static final Point3D DEFAULT_EYE = new Point3D(0, 1, 6);
    static final Point3D DEFAULT_LOOK_AT = new Point3D(0, 0.5, 0);
    static final double DEFAULT_FOV = 45;
    static final double DEFAULT_VIEW_HEIGHT = 4;

    private CameraReader() {
    }

    /**
     * A camera as the file gives it. {@code focalDistance} is NaN when the file leaves it to the
     * distance from eye to look-at, which then follows an animated eye; {@code fov} is NaN for the
     * orthographic camera, which has none.
     */
    record Spec(String kind, Point3D eye, Point3D lookAt, Vector3D up, double fov, double lensRadius, double focalDistance,
                double viewHeight) {

        Spec withView(Point3D eye, Point3D lookAt, Vector3D up, double fov) {
            return new Spec(kind, eye, lookAt, up, fov, lensRadius, focalDistance, viewHeight);
        }

        /** The camera; IllegalArgumentException says what is wrong with the values. */
        Camera make() {
            return switch (kind) {
                case "pinhole" -> new Pinhole(eye, lookAt, up, fov);
                case "thin-lens" -> new ThinLens(eye, lookAt, up, fov, lensRadius,
                                                 Double.isNaN(focalDistance) ? eye.distance(lookAt) : focalDistance);
                default -> new Orthographic(eye, lookAt, up, viewHeight);
            };
        }
    }

    static Spec defaultSpec() {
        return new Spec("pinhole", DEFAULT_EYE, DEFAULT_LOOK_AT, Vector3D.UP, DEFAULT_FOV, 0, Double.NaN, DEFAULT_VIEW_HEIGHT);
    }

    static Camera defaultCamera() {
        return defaultSpec().make();
    }

    static Camera read(Source source, Node node) throws SceneException {
        return make(source, node, spec(source, node));
    }

    /** {@code spec}'s camera, or the error of its values pointing at {@code node}. */
    static Camera make(Source source, Node node, Spec spec) throws SceneException {
        try {
            return spec.make();
        } catch (IllegalArgumentException e) {
            throw source.error(node, e.getMessage());
        }
    }

    static Spec spec(Source source, Node node) throws SceneException {
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
        return switch (kind) {
            case "pinhole" -> new Spec(kind, eye, lookAt, up, c.number("fov", DEFAULT_FOV), 0, Double.NaN, DEFAULT_VIEW_HEIGHT);
            case "thin-lens" -> new Spec(kind, eye, lookAt, up, c.number("fov", DEFAULT_FOV), c.number("lens-radius", 0.05),
                                         c.has("focal-distance") ? c.number("focal-distance", 1) : Double.NaN, DEFAULT_VIEW_HEIGHT);
            default -> new Spec(kind, eye, lookAt, up, Double.NaN, 0, Double.NaN, c.number("view-height", DEFAULT_VIEW_HEIGHT));
        };
    }
}

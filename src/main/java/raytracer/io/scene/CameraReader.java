package raytracer.io.scene;

import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.cameras.Orthographic;
import raytracer.cameras.Pinhole;
import raytracer.cameras.ThinLens;
import raytracer.core.Camera;
import raytracer.core.CameraFactory;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.core.Plugin;
import raytracer.core.Registry;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * The {@code camera} section, of a type of the {@link Registry}: the built-in pinhole, thin-lens
 * and orthographic cameras are made here and registered by {@link BuiltInTypes}.
 */
final class CameraReader {
    static final Point3D DEFAULT_EYE = new Point3D(0, 1, 6);
    static final Point3D DEFAULT_LOOK_AT = new Point3D(0, 0.5, 0);
    static final double DEFAULT_FOV = 45;
    static final double DEFAULT_VIEW_HEIGHT = 4;
    /** The keys of every camera: where it stands and looks. */
    private static final Set<String> COMMON = Set.of("type", "eye", "look-at", "up");

    private CameraReader() {
    }

    static Camera defaultCamera() {
        return new Pinhole(DEFAULT_EYE, DEFAULT_LOOK_AT, Vector3D.UP, DEFAULT_FOV);
    }

    static Camera read(Source source, Node node) throws SceneException {
        String kind = YamlObject.peekType(source, node, "camera", "pinhole");
        Plugin<CameraFactory> type = RegisteredType.find(Registry.standard().cameras(), "camera", kind, source, node);
        YamlObject c = new YamlObject(source, node, kind + " camera", RegisteredType.keys(COMMON, type));
        Point3D eye = c.point("eye", DEFAULT_EYE);
        Point3D lookAt = c.point("look-at", DEFAULT_LOOK_AT);
        Vector3D up = c.vector("up", Vector3D.UP);
        return new YamlParameters(c, null).make(p -> type.make().make(eye, lookAt, up, p), node, "");
    }

    static Camera pinhole(Point3D eye, Point3D lookAt, Vector3D up, Parameters c) throws ParameterException {
        return new Pinhole(eye, lookAt, up, c.number("fov", DEFAULT_FOV));
    }

    static Camera thinLens(Point3D eye, Point3D lookAt, Vector3D up, Parameters c) throws ParameterException {
        return new ThinLens(eye, lookAt, up, c.number("fov", DEFAULT_FOV), c.number("lens-radius", 0.05),
                            c.number("focal-distance", eye.distance(lookAt)));
    }

    static Camera orthographic(Point3D eye, Point3D lookAt, Vector3D up, Parameters c) throws ParameterException {
        return new Orthographic(eye, lookAt, up, c.number("view-height", DEFAULT_VIEW_HEIGHT));
    }
}

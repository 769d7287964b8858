package raytracer.io.scene;

import java.nio.file.Path;
import java.util.List;
import java.util.OptionalInt;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.ViewPlane;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.reference.ExactLight;
import raytracer.reference.LitPlane;
import raytracer.reference.ParallelDiskLight;
import raytracer.reference.PolygonLight;

/**
 * Reads the exact image of a scene that has one ({@link LitPlane}): an orthographic camera, one
 * plane of untextured matte material, and one invisible rectangle or disk area light (the disk
 * parallel to the plane). Anything else is a SceneException saying what keeps the scene from
 * having one. The whole scene is loaded first, so its keys are checked as for rendering; this
 * class reads again only the values the image depends on, with the loader's defaults.
 */
public final class ClosedFormReader {
    private ClosedFormReader() {
    }

    public static LitPlane read(Path file) throws SceneException {
        return read(SceneLoader.source(file), SceneLoader.text(file));
    }

    /** Reads scene text; {@code sourceName} is used in messages. */
    public static LitPlane read(String sourceName, String text) throws SceneException {
        return read(new Source(sourceName, null), text);
    }

    private static LitPlane read(Source source, String text) throws SceneException {
        ViewPlane vp = SceneLoader.load(source, text, OptionalInt.empty(), null).world().viewPlane();
        Node root = SceneLoader.root(source, text);
        YamlObject scene = new YamlObject(source, root, "the scene", SceneLoader.FILE_SECTIONS);
        if (scene.has("animation")) {
            throw refuse(source, scene.raw("animation"), "the scene is animated (an exact image is of a still scene)");
        }
        String pass = scene.string("pass", "full");
        if (!pass.equals("full") && !pass.equals("direct")) {
            throw refuse(source, scene.raw("pass"), "the pass must be full or direct, not " + pass);
        }
        if (!scene.has("camera") || !YamlObject.peekType(source, scene.raw("camera"), "camera", "pinhole").equals("orthographic")) {
            throw refuse(source, scene.has("camera") ? scene.raw("camera") : root, "the camera must be orthographic");
        }
        YamlObject camera = new YamlObject(source, scene.raw("camera"), "camera", AnyName.INSTANCE);
        RGBColor ambientLight = RGBColor.WHITE.scale(SettingsReader.AMBIENT_RADIANCE);
        if (scene.has("ambient")) {
            YamlObject a = new YamlObject(source, scene.raw("ambient"), "ambient", AnyName.INSTANCE);
            ambientLight = a.color("color", RGBColor.WHITE).scale(a.number("radiance", SettingsReader.AMBIENT_RADIANCE));
        }
        List<Node> objects = scene.list("objects");
        if (objects.size() != 1 || !YamlObject.peekType(source, objects.get(0), "object", null).equals("plane")) {
            throw refuse(source, scene.raw("objects"), "the scene must hold one object, a plane");
        }
        YamlObject plane = new YamlObject(source, objects.get(0), "plane", AnyName.INSTANCE);
        if (plane.has("transform")) {
            throw refuse(source, plane.raw("transform"), "the plane must have no transform");
        }
        YamlObject material = material(source, scene, plane);
        RGBColor cd = material == null ? RGBColor.gray(MaterialReader.DEFAULT_GREY) : material.color("color", RGBColor.WHITE);
        double ka = material == null ? MaterialReader.KA : material.number("ka", MaterialReader.KA);
        double kd = material == null ? MaterialReader.KD : material.number("kd", MaterialReader.KD);
        Vector3D normal = plane.requiredVector("normal").normalize();
        List<Node> lights = scene.list("lights");
        if (lights.size() != 1) {
            throw refuse(source, scene.has("lights") ? scene.raw("lights") : root, "the scene must have exactly one light");
        }
        YamlObject light = new YamlObject(source, lights.get(0), "light", AnyName.INSTANCE);
        RGBColor radiance = light.color("color", RGBColor.WHITE).scale(light.number("radiance", LightReader.AREA_RADIANCE));
        try {
            return new LitPlane(vp.hres(), vp.vres(), camera.point("eye", CameraReader.DEFAULT_EYE),
                                camera.point("look-at", CameraReader.DEFAULT_LOOK_AT), camera.vector("up", Vector3D.UP),
                                camera.number("view-height", CameraReader.DEFAULT_VIEW_HEIGHT), plane.point("point", Point3D.ORIGIN),
                                normal, cd.scale(kd), cd.scale(ka).mul(ambientLight), radiance, exactLight(source, light, normal),
                                vp.exposure());
        } catch (IllegalArgumentException e) {
            throw refuse(source, root, e.getMessage());
        }
    }

    /** The plane's material mapping, or null for the default material; it must be untextured matte. */
    private static YamlObject material(Source source, YamlObject scene, YamlObject plane) throws SceneException {
        if (!plane.has("material")) {
            return null;
        }
        Node node = new YamlObject(source, scene.raw("materials"), "materials", AnyName.INSTANCE)
            .raw(plane.requiredString("material"));
        if (!YamlObject.peekType(source, node, "material", "matte").equals("matte")) {
            throw refuse(source, node, "the plane's material must be matte");
        }
        YamlObject m = new YamlObject(source, node, "material", AnyName.INSTANCE);
        if (m.has("texture")) {
            throw refuse(source, m.raw("texture"), "the plane's material must have no texture");
        }
        return m;
    }

    private static ExactLight exactLight(Source source, YamlObject light, Vector3D planeNormal) throws SceneException {
        String kind = YamlObject.peekType(source, light.node(), "light", null);
        if (light.bool("visible", true)) {
            throw refuse(source, light.node(), "the light must be 'visible: false' (its surface would be in the picture)");
        }
        switch (kind) {
            case "rectangle" -> {
                return PolygonLight.rectangle(light.requiredPoint("corner"), light.requiredVector("edge-a"),
                                              light.requiredVector("edge-b"));
            }
            case "disk" -> {
                Vector3D axis = light.requiredVector("normal").normalize();
                if (!(axis.dot(planeNormal) < -1 + 1e-12)) {
                    throw refuse(source, light.raw("normal"), "a disk light must be parallel to the plane and face it");
                }
                return new ParallelDiskLight(light.requiredPoint("center"), light.number("radius", LightReader.AREA_RADIUS));
            }
            default -> throw refuse(source, light.node(), "the light must be a rectangle or a disk, not " + kind);
        }
    }

    private static SceneException refuse(Source source, Node node, String why) {
        return source.error(node, "no closed form: " + why);
    }
}

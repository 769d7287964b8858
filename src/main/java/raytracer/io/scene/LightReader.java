package raytracer.io.scene;

import java.util.OptionalInt;
import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.GeometricObject;
import raytracer.core.Light;
import raytracer.core.Sampler;
import raytracer.core.World;
import raytracer.lights.AreaLight;
import raytracer.lights.Directional;
import raytracer.lights.PointLight;
import raytracer.materials.Emissive;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.shapes.Disk;
import raytracer.shapes.Rectangle;
import raytracer.shapes.Sphere;

/** One entry of the {@code lights} list: point, directional or an area light. */
final class LightReader {
    private LightReader() {
    }

    static final int AREA_SAMPLES = 16;
    static final double AREA_RADIANCE = 1;
    static final double AREA_RADIUS = 1;

    /**
     * Reads a light; an area light that is {@code visible} also adds its emitting shape to the world.
     * {@code areaLightSamples}, when present, replaces every area light's {@code samples}.
     */
    static Light read(Source source, Node node, World world, OptionalInt areaLightSamples) throws SceneException {
        String kind = YamlObject.peekType(source, node, "light", null);
        YamlObject common = null;
        Light light = switch (kind) {
            case "point" -> {
                YamlObject l = new YamlObject(source, node, "point light", Set.of("type", "position", "intensity", "color", "shadows"));
                common = l;
                double intensity = l.number("intensity", 1, 0, false);
                RGBColor color = l.color("color", RGBColor.WHITE);
                l.checkEmission("intensity", intensity, "color", color);
                yield new PointLight(intensity, color, l.requiredPoint("position"));
            }
            case "directional" -> {
                YamlObject l = new YamlObject(source, node, "directional light", Set.of("type", "direction", "radiance", "color", "shadows"));
                common = l;
                double radiance = l.number("radiance", 1, 0, false);
                RGBColor color = l.color("color", RGBColor.WHITE);
                l.checkEmission("radiance", radiance, "color", color);
                try {
                    yield new Directional(radiance, color, l.requiredVector("direction"));
                } catch (IllegalArgumentException e) {
                    throw source.error(l.raw("direction"), e.getMessage());
                }
            }
            case "rectangle", "disk", "sphere" -> {
                common = new YamlObject(source, node, kind + " light", areaKeys(kind));
                yield area(common, kind, world, areaLightSamples);
            }
            default -> throw source.error(YamlObject.typeNode(node),
                "unknown light type '" + kind + "'; allowed: directional, disk, point, rectangle, sphere");
        };
        light.setCastsShadows(common.bool("shadows", true));
        return light;
    }

    private static Set<String> areaKeys(String kind) {
        Set<String> keys = new java.util.HashSet<>(Set.of("type", "radiance", "color", "samples", "visible", "shadows"));
        keys.addAll(switch (kind) {
            case "rectangle" -> Set.of("corner", "edge-a", "edge-b");
            case "disk" -> Set.of("center", "normal", "radius");
            default -> Set.of("center", "radius");
        });
        return keys;
    }

    /**
     * An area light of radiance {@code radiance color}; the emitting shape, if visible, is an
     * emissive object that casts no shadow (the light's own samples lie on it).
     */
    private static Light area(YamlObject l, String kind, World world, OptionalInt areaLightSamples) throws SceneException {
        double ls = l.number("radiance", AREA_RADIANCE, 0, false);
        RGBColor color = l.color("color", RGBColor.WHITE);
        l.checkEmission("radiance", ls, "color", color);
        int samples = l.integer("samples", AREA_SAMPLES, 1, Sampler.MAX_SAMPLES);
        if (areaLightSamples.isPresent()) {
            samples = areaLightSamples.getAsInt();
        }
        Light light;
        GeometricObject shape;
        try {
            switch (kind) {
                case "rectangle" -> {
                    Point3D corner = l.requiredPoint("corner");
                    Vector3D a = l.requiredVector("edge-a");
                    Vector3D b = l.requiredVector("edge-b");
                    light = AreaLight.rectangle(corner, a, b, ls, color, samples);
                    shape = new Rectangle(corner, a, b);
                }
                case "disk" -> {
                    Point3D center = l.requiredPoint("center");
                    Vector3D normal = l.requiredVector("normal");
                    double radius = l.number("radius", AREA_RADIUS, 0, true);
                    light = AreaLight.disk(center, normal, radius, ls, color, samples);
                    shape = new Disk(center, normal, radius);
                }
                default -> {
                    Point3D center = l.requiredPoint("center");
                    double radius = l.number("radius", AREA_RADIUS, 0, true);
                    light = AreaLight.sphere(center, radius, ls, color, samples);
                    shape = new Sphere(center, radius);
                }
            }
        } catch (IllegalArgumentException e) {
            throw l.source().error(l.node(), e.getMessage());
        }
        if (l.bool("visible", true)) {
            shape.setMaterial(new Emissive(ls, color, light));
            shape.setCastsShadows(false);
            world.addObject(shape);
        }
        return light;
    }
}

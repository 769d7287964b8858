package raytracer.io.scene;

import java.util.List;
import java.util.OptionalInt;
import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Factory;
import raytracer.core.GeometricObject;
import raytracer.core.Light;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.core.Plugin;
import raytracer.core.Registry;
import raytracer.core.Sampler;
import raytracer.core.World;
import raytracer.lights.Ambient;
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

/**
 * One entry of the {@code lights} list, of a type of the {@link Registry}: the built-in point,
 * directional and area lights (made here, registered by {@link BuiltInTypes}) or a registered one.
 */
final class LightReader {
    private LightReader() {
    }

    static final int AREA_SAMPLES = 16;
    static final double AREA_RADIANCE = 1;
    static final double AREA_RADIUS = 1;
    /** The keys of every light. */
    private static final Set<String> COMMON = Set.of("type", "shadows");

    /** What an area light needs beside its values: the world its visible shape joins, and the samples override. */
    record Context(World world, OptionalInt areaLightSamples) {
    }

    /**
     * Reads a light; an area light that is {@code visible} also adds its emitting shape to the world.
     * {@code areaLightSamples}, when present, replaces every area light's {@code samples}.
     */
    static Light read(Source source, Node node, World world, OptionalInt areaLightSamples) throws SceneException {
        String kind = YamlObject.peekType(source, node, "light", null);
        Plugin<Factory<Light>> type = RegisteredType.find(Registry.standard().lights(), "light", kind, source, node);
        YamlObject l = new YamlObject(source, node, kind + " light", RegisteredType.keys(COMMON, type));
        Light light = new YamlParameters(l, new Context(world, areaLightSamples)).make(type.make(), node, "");
        light.setCastsShadows(l.bool("shadows", true));
        return light;
    }

    static Light point(Parameters l) throws ParameterException {
        double intensity = l.number("intensity", 1, 0, false);
        RGBColor color = l.color("color", RGBColor.WHITE);
        l.checkEmission("intensity", intensity, "color", color);
        return new PointLight(intensity, color, l.requiredPoint("position"));
    }

    static Light directional(Parameters l) throws ParameterException {
        double radiance = l.number("radiance", 1, 0, false);
        RGBColor color = l.color("color", RGBColor.WHITE);
        l.checkEmission("radiance", radiance, "color", color);
        Vector3D direction = l.requiredVector("direction");
        try {
            return new Directional(radiance, color, direction);
        } catch (IllegalArgumentException e) {
            throw l.error("direction", e.getMessage());
        }
    }

    /** The world's ambient light of the book (chapter 14): {@code ambient: {radiance, color}}. */
    static Light constantAmbient(Parameters a) throws ParameterException {
        double radiance = a.number("radiance", SettingsReader.AMBIENT_RADIANCE, 0, false);
        RGBColor color = a.color("color", RGBColor.WHITE);
        a.checkEmission("radiance", radiance, "color", color);
        return new Ambient(radiance, color);
    }

    static Light rectangle(YamlParameters p) throws SceneException {
        YamlObject l = p.values();
        Emission e = emission(l, p.context(Context.class));
        Point3D corner = l.requiredPoint("corner");
        Vector3D a = l.requiredVector("edge-a");
        Vector3D b = l.requiredVector("edge-b");
        AreaLight light = AreaLight.rectangle(corner, a, b, e.ls, e.color, e.samples);
        String sampling = l.choice("sampling", "auto", List.of("auto", "solid-angle", "area"));
        if (!sampling.equals("auto")) {
            try {
                light.sampleBySolidAngle(sampling.equals("solid-angle"));
            } catch (IllegalArgumentException ex) {
                throw l.error("sampling", ex.getMessage());
            }
        }
        return visible(p, e, light, new Rectangle(corner, a, b));
    }

    static Light disk(YamlParameters p) throws SceneException {
        YamlObject l = p.values();
        Emission e = emission(l, p.context(Context.class));
        Point3D center = l.requiredPoint("center");
        Vector3D normal = l.requiredVector("normal");
        double radius = l.number("radius", AREA_RADIUS, 0, true);
        return visible(p, e, AreaLight.disk(center, normal, radius, e.ls, e.color, e.samples), new Disk(center, normal, radius));
    }

    static Light sphere(YamlParameters p) throws SceneException {
        YamlObject l = p.values();
        Emission e = emission(l, p.context(Context.class));
        Point3D center = l.requiredPoint("center");
        double radius = l.number("radius", AREA_RADIUS, 0, true);
        return visible(p, e, AreaLight.sphere(center, radius, e.ls, e.color, e.samples), new Sphere(center, radius));
    }

    /** An area light's radiance {@code ls color} and its samples per shaded point. */
    private record Emission(double ls, RGBColor color, int samples) {
    }

    private static Emission emission(YamlObject l, Context context) throws SceneException {
        double ls = l.number("radiance", AREA_RADIANCE, 0, false);
        RGBColor color = l.color("color", RGBColor.WHITE);
        l.checkEmission("radiance", ls, "color", color);
        int samples = l.integer("samples", AREA_SAMPLES, 1, Sampler.MAX_SAMPLES);
        if (context.areaLightSamples().isPresent()) {
            samples = context.areaLightSamples().getAsInt();
        }
        return new Emission(ls, color, samples);
    }

    /**
     * The area light; its emitting shape, if visible, is an emissive object that casts no shadow
     * (the light's own samples lie on it).
     */
    private static Light visible(YamlParameters p, Emission e, Light light, GeometricObject shape) throws SceneException {
        if (p.values().bool("visible", true)) {
            shape.setMaterial(new Emissive(e.ls, e.color, light));
            shape.setCastsShadows(false);
            p.context(Context.class).world().addObject(shape);
        }
        return light;
    }
}

package raytracer.io.scene;

import java.util.HashSet;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Factory;
import raytracer.core.Light;
import raytracer.core.PixelFilter;
import raytracer.core.Plugin;
import raytracer.core.Plugins;
import raytracer.core.Registry;
import raytracer.core.Sampler;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.DisplayEncoding;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.RGBColor;
import raytracer.samplers.Samplers;
import raytracer.tracers.AreaLighting;
import raytracer.tracers.RayCast;
import raytracer.tracers.Whitted;

/**
 * A scene file's render settings: the image section (size, samples and their pattern, depth,
 * exposure, pixel filter, the adaptive cutoff, the encoding of the PNG), the tracer and the
 * ambient light.
 */
final class SettingsReader {
    static final double AMBIENT_RADIANCE = 0.1;
    /** The image section's keys: its own and those of the registered filters ({@code filter-stddev}). */
    static final Set<String> IMAGE_KEYS = union(Registry.standard().filters().keys(),
                                                Set.of("width", "height", "samples", "sampler", "max-depth", "exposure", "cutoff",
                                                       "encoding", "filter"));

    private SettingsReader() {
    }

    private static Set<String> union(Set<String> a, Set<String> b) {
        Set<String> all = new HashSet<>(a);
        all.addAll(b);
        return Set.copyOf(all);
    }

    static ViewPlane readImage(Source source, YamlObject scene) throws SceneException {
        YamlObject image = scene.has("image")
            ? new YamlObject(source, scene.raw("image"), "image", IMAGE_KEYS)
            : null;
        if (image == null) {
            return new ViewPlane(640, 360, 4, Samplers.byName("multi-jittered"), 5, 1);
        }
        String samplerName = image.string("sampler", "multi-jittered");
        if (!Samplers.names().contains(samplerName)) {
            throw source.error(image.raw("sampler"), "unknown sampler '" + samplerName + "'; allowed: "
                               + String.join(", ", Samplers.names()));
        }
        int width = image.integer("width", 640, 1);
        int height = image.integer("height", 360, 1);
        if ((long) width * height > Film.MAX_PIXELS) {
            throw source.error(image.has("width") ? image.raw("width") : image.raw("height"), "an image of " + width + " x "
                               + height + " pixels is not possible: it holds at most " + Film.MAX_PIXELS + " pixels");
        }
        return new ViewPlane(width, height,
                             image.integer("samples", 4, 1, Sampler.MAX_SAMPLES), Samplers.byName(samplerName),
                             image.integer("max-depth", 5, 0, ViewPlane.MAX_DEPTH), image.number("exposure", 1, 0, true),
                             readFilter(source, image));
    }

    /**
     * The image's filter, of the {@link Registry}'s, with its keys: a key of another filter (a
     * width given to the box) is refused naming the filter that has it.
     */
    private static PixelFilter readFilter(Source source, YamlObject image) throws SceneException {
        String name = image.string("filter", "box");
        Plugins<Factory<PixelFilter>> filters = Registry.standard().filters();
        Plugin<Factory<PixelFilter>> filter = filters.find(name).orElseThrow(() -> source.error(image.raw("filter"), "unknown filter '"
            + name + "'; allowed: " + String.join(", ", filters.names())));
        for (String key : new java.util.TreeSet<>(filters.keys())) {
            if (image.has(key) && !filter.keys().contains(key)) {
                throw source.error(image.raw(key), "'" + key + "' in image is for filter: " + filters.withKey(key).orElseThrow().name()
                                                   + ", not " + name);
            }
        }
        // what a filter's constructor refuses is its width: the message goes to the key that gave it
        Node where = filter.keys().stream().filter(image::has).findFirst().map(image::raw)
            .orElse(image.has("filter") ? image.raw("filter") : image.node());
        return new YamlParameters(image, null).make(filter.make(), where, "");
    }

    /**
     * Suffern's tracers: area-lighting, the default when a light has extent, whitted otherwise, or
     * ray-cast. Whitted and ray-cast take each light from one direction, so they are refused for a
     * scene with area lights rather than render it without them.
     */
    static Function<World, Tracer> readTracer(Source source, YamlObject scene, boolean areaLights)
            throws SceneException {
        String name = scene.string("tracer", areaLights ? "area-lighting" : "whitted");
        Function<World, Tracer> tracer = switch (name) {
            case "area-lighting" -> AreaLighting::new;
            case "whitted" -> Whitted::new;
            case "ray-cast" -> RayCast::new;
            default -> throw source.error(scene.raw("tracer"), "unknown tracer '" + name
                                          + "'; allowed: area-lighting, ray-cast, whitted");
        };
        if (areaLights && !name.equals("area-lighting")) {
            throw source.error(scene.raw("tracer"), "tracer '" + name + "' cannot sample the scene's area lights; "
                               + "use area-lighting (the default with area lights; max-depth: 0 for direct light only)");
        }
        return tracer;
    }

    static double readCutoff(Source source, YamlObject scene) throws SceneException {
        if (!scene.has("image")) {
            return 0;
        }
        YamlObject image = new YamlObject(source, scene.raw("image"), "image", IMAGE_KEYS);
        double cutoff = image.number("cutoff", 0, 0, false);
        if (cutoff >= 1) {
            throw source.error(image.raw("cutoff"), "'cutoff' in image must be below 1, got " + cutoff);
        }
        return cutoff;
    }

    static DisplayEncoding readEncoding(Source source, YamlObject scene) throws SceneException {
        if (!scene.has("image")) {
            return DisplayEncoding.SRGB;
        }
        YamlObject image = new YamlObject(source, scene.raw("image"), "image", IMAGE_KEYS);
        String encoding = image.string("encoding", "srgb");
        Optional<DisplayEncoding> named = DisplayEncoding.named(encoding);
        if (named.isEmpty()) {
            throw source.error(image.raw("encoding"), "unknown encoding '" + encoding + "'; allowed: " + DisplayEncoding.NAMES);
        }
        return named.get();
    }

    /**
     * The world's ambient light: the book's constant one unless another is registered and chosen
     * by {@code type}, a key only once there is a choice (so a scene's keys are checked as before).
     */
    static Light readAmbient(Source source, YamlObject scene) throws SceneException {
        if (!scene.has("ambient")) {
            return new Ambient(AMBIENT_RADIANCE, RGBColor.WHITE);
        }
        Node node = scene.raw("ambient");
        Plugins<Factory<Light>> ambients = Registry.standard().ambients();
        boolean typed = ambients.names().size() > 1;
        String kind = typed ? YamlObject.peekType(source, node, "ambient", "constant") : "constant";
        Plugin<Factory<Light>> type = RegisteredType.find(ambients, "ambient", kind, source, node);
        YamlObject a = new YamlObject(source, node, "ambient", RegisteredType.keys(typed ? Set.of("type") : Set.of(), type));
        return new YamlParameters(a, null).make(type.make(), node, "");
    }
}

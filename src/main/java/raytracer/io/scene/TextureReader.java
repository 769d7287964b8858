package raytracer.io.scene;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Factory;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.core.Plugin;
import raytracer.core.Registry;
import raytracer.core.Texture;
import raytracer.image.Film;
import raytracer.image.ImageFiles;
import raytracer.math.RGBColor;
import raytracer.textures.Checker;
import raytracer.textures.ConstantColor;
import raytracer.textures.EnvironmentMap;
import raytracer.textures.ImageTexture;

/**
 * Textures ({@code texture: {type: checker | constant | image, ...}}, of the types of the
 * {@link Registry}; the built-in ones are made here and registered by {@link BuiltInTypes}) and
 * environment maps ({@code {file: x.hdr, intensity: 1}}). Each image file is read once per scene.
 */
final class TextureReader {
    private static final Set<String> COMMON = Set.of("type");

    /** The images read, by file: as colours, and as data (normal maps); the frames of an animation share them. */
    record Images(Map<Path, Film> colors, Map<Path, Film> data) {
        Images() {
            this(new HashMap<>(), new HashMap<>());
        }
    }

    private final Source source;
    private final Map<Path, Film> images;
    private final Map<Path, Film> linearImages;

    /** The files read are noted in {@code inputs}. */
    private final LoadReport inputs;

    TextureReader(Source source) {
        this(source, new LoadReport());
    }

    TextureReader(Source source, LoadReport inputs) {
        this(source, inputs, new Images());
    }

    /** Reusing the images in {@code images} and keeping those it reads there. */
    TextureReader(Source source, LoadReport inputs, Images images) {
        this.source = source;
        this.inputs = inputs;
        this.images = images.colors();
        this.linearImages = images.data();
    }

    Texture texture(Node node) throws SceneException {
        String kind = YamlObject.peekType(source, node, "texture", null);
        Plugin<Factory<Texture>> type = RegisteredType.find(Registry.standard().textures(), "texture", kind, source, node);
        YamlObject t = new YamlObject(source, node, kind + " texture", RegisteredType.keys(COMMON, type));
        return new YamlParameters(t, this).make(type.make(), node, "");
    }

    static Texture checker(Parameters t) throws ParameterException {
        return new Checker(t.color("color-a", RGBColor.WHITE), t.color("color-b", RGBColor.gray(0.1)), t.number("size", 0.1, 0, true));
    }

    static Texture constant(Parameters t) throws ParameterException {
        return new ConstantColor(t.color("color", RGBColor.WHITE));
    }

    /** An image file, read once per scene by the reader that reads the texture. */
    static Texture imageTexture(YamlParameters p) throws SceneException {
        return new ImageTexture(p.context(TextureReader.class).image(p.values()));
    }

    EnvironmentMap environment(Node node, String what) throws SceneException {
        YamlObject e = new YamlObject(source, node, what, Set.of("file", "intensity", "rotate-y"));
        Film map = image(e);
        double intensity = e.number("intensity", 1, 0, false);
        e.checkEmission("intensity", intensity, "file", "the brightest pixel of " + e.path("file"),
                        brightest(map));
        return new EnvironmentMap(map, intensity, e.number("rotate-y", 0));
    }

    private static double brightest(Film film) {
        double max = 0;
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                max = Math.max(max, Math.max(film.get(x, y, 0), Math.max(film.get(x, y, 1), film.get(x, y, 2))));
            }
        }
        return max;
    }

    /** Reads (or reuses) an image for a file path given relative to the scene, naming the path on failure. */
    Film image(Path path, Node where) throws SceneException {
        return image(path, where, true);
    }

    /** A normal map: the same, but its bytes are data, not sRGB colours. */
    Film linearImage(Path path, Node where) throws SceneException {
        return image(path, where, false);
    }

    private Film image(Path path, Node where, boolean srgb) throws SceneException {
        Map<Path, Film> cache = srgb ? images : linearImages;
        Film film = cache.get(path);
        inputs.addInput(path);
        if (film == null) {
            try {
                film = ImageFiles.read(path, srgb);
            } catch (IOException e) {
                throw where != null ? source.error(where, e.getMessage()) : new SceneException(e.getMessage(), e);
            }
            cache.put(path, film);
        }
        return film;
    }

    private Film image(YamlObject o) throws SceneException {
        return image(o.path("file"), o.raw("file"));
    }
}

package raytracer.io.scene;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Texture;
import raytracer.image.Film;
import raytracer.image.ImageFiles;
import raytracer.math.RGBColor;
import raytracer.textures.Checker;
import raytracer.textures.ConstantColor;
import raytracer.textures.EnvironmentMap;
import raytracer.textures.ImageTexture;

/**
 * Textures ({@code texture: {type: checker | constant | image, ...}}) and environment maps
 * ({@code {file: x.hdr, intensity: 1}}). Each image file is read once per scene.
 */
final class TextureReader {
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
        switch (kind) {
            case "checker" -> {
                YamlObject t = new YamlObject(source, node, "checker texture", Set.of("type", "color-a", "color-b", "size"));
                return new Checker(t.color("color-a", RGBColor.WHITE), t.color("color-b", RGBColor.gray(0.1)),
                                   t.number("size", 0.1, 0, true));
            }
            case "constant" -> {
                YamlObject t = new YamlObject(source, node, "constant texture", Set.of("type", "color"));
                return new ConstantColor(t.color("color", RGBColor.WHITE));
            }
            case "image" -> {
                YamlObject t = new YamlObject(source, node, "image texture", Set.of("type", "file"));
                return new ImageTexture(image(t));
            }
            default -> throw source.error(YamlObject.typeNode(node), "unknown texture type '" + kind + "'; allowed: checker, constant, image");
        }
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

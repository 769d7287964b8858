package raytracer.io.scene;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.cache.MeshCache;
import raytracer.core.Camera;
import raytracer.core.Light;
import raytracer.core.Material;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.DisplayEncoding;
import raytracer.math.Matrix4;
import raytracer.math.RGBColor;

/**
 * A scene file read once, from which the world of any frame is loaded: the text is parsed into
 * YAML nodes once, the image settings and the animation are read once (and can be asked for
 * without building anything), and each mesh and image file is read once for every frame. Each
 * {@link #load} makes a new {@link World} with that frame's camera and object transforms, since
 * the scene analysis and {@link World#prepare} change a world for the one view they are made for
 * (a world prepared for one frame must not serve another). A still is an animation of one frame.
 */
public final class SceneFile {
    private final Source source;
    private final Node root;
    private final YamlObject scene;
    private final Path file;
    private final ViewPlane viewPlane;
    private final RayTreeSettings rayTree;
    private final DisplayEncoding encoding;
    /** Null for a still. */
    private final Animation animation;
    private final OptionalInt areaLightSamples;
    private final MeshCache cache;
    /** What every frame shares: the meshes by file and options, the images by file. */
    private final Map<String, SharedMesh> meshes = new HashMap<>();
    private final TextureReader.Images images = new TextureReader.Images();

    private SceneFile(Source source, String text, Path file, OptionalInt areaLightSamples, MeshCache cache) throws SceneException {
        this.source = source;
        this.file = file;
        this.areaLightSamples = areaLightSamples;
        this.cache = cache;
        this.root = SceneLoader.root(source, text);
        this.scene = new YamlObject(source, root, "the scene", SceneLoader.FILE_SECTIONS);
        this.viewPlane = SettingsReader.readImage(source, scene);
        RayTreeSettings tree = RayTreeSettings.FULL_TREE.withCutoff(SettingsReader.readCutoff(source, scene));
        if (scene.has("pass")) {
            try {
                tree = tree.withPass(ShadingPass.parse(scene.requiredString("pass")));
            } catch (IllegalArgumentException e) {
                throw source.error(scene.raw("pass"), e.getMessage());
            }
        }
        this.rayTree = tree;
        this.encoding = SettingsReader.readEncoding(source, scene);
        this.animation = scene.has("animation")
            ? Animation.read(source, scene.raw("animation"), scene.has("camera")
                             && YamlObject.peekType(source, scene.raw("camera"), "camera", "pinhole").equals("orthographic"))
            : null;
        checkNames();
    }

    /** Reads the scene file {@code file}; its meshes come from {@code cache} when it has them (null: no cache). */
    public static SceneFile read(Path file, MeshCache cache) throws SceneException {
        return read(file, cache, OptionalInt.empty());
    }

    /**
     * As {@link #read(Path, MeshCache)}; with {@code areaLightSamples} every area light takes that
     * many samples per shaded point instead of its {@code samples} key (the convergence benchmark's override).
     */
    public static SceneFile read(Path file, MeshCache cache, OptionalInt areaLightSamples) throws SceneException {
        return new SceneFile(SceneLoader.source(file), SceneLoader.text(file), file, areaLightSamples, cache);
    }

    /**
     * The text of the scene file {@code file}, checked as {@link #read} checks it (UTF-8, at most
     * the characters a scene may hold); a SceneException says why it cannot be read.
     */
    public static String readText(Path file) throws SceneException {
        return SceneLoader.text(file);
    }

    /**
     * The scene file {@code file} whose text is {@code text}, already read (by another machine: a
     * render farm's driver sends it); relative paths start at {@code file}'s folder.
     */
    public static SceneFile of(Path file, String text, MeshCache cache, OptionalInt areaLightSamples) throws SceneException {
        return new SceneFile(SceneLoader.source(file), text, file, areaLightSamples, cache);
    }

    /** Scene text named {@code sourceName} in messages; relative paths start at the working directory. */
    public static SceneFile of(String sourceName, String text) throws SceneException {
        return of(sourceName, text, OptionalInt.empty());
    }

    /** As {@link #of(String, String)}, every area light taking {@code areaLightSamples} when present. */
    public static SceneFile of(String sourceName, String text, OptionalInt areaLightSamples) throws SceneException {
        return new SceneFile(new Source(sourceName, null), text, null, areaLightSamples, null);
    }

    static SceneFile of(Source source, String text, OptionalInt areaLightSamples, MeshCache cache) throws SceneException {
        return new SceneFile(source, text, null, areaLightSamples, cache);
    }

    /** Every object's name must be unique, and every object the animation moves must be named so. */
    private void checkNames() throws SceneException {
        Map<String, Node> named = new HashMap<>();
        if (scene.raw("objects") instanceof org.yaml.snakeyaml.nodes.SequenceNode) {
            for (Node object : scene.list("objects")) {
                String name = ObjectReader.name(source, object);
                if (name != null && named.put(name, object) != null) {
                    throw source.error(object, "two objects are named '" + name + "'; an object's name must be unique");
                }
            }
        }
        if (animation != null) {
            for (Map.Entry<String, Node> moved : animation.objectNodes().entrySet()) {
                if (!named.containsKey(moved.getKey())) {
                    throw source.error(moved.getValue(), "the animation moves object '" + moved.getKey() + "', but no object has "
                                       + "that name; named: " + (named.isEmpty() ? "none (give an object name: ...)"
                                                                                  : YamlScalars.names(named.keySet())));
                }
            }
        }
    }

    /** The image settings as the file gives them: size, samples, sampler, depth, exposure, filter. Nothing is built. */
    public ViewPlane viewPlane() {
        return viewPlane;
    }

    /** How much of the ray tree the file asks to trace ({@code pass}, {@code image.cutoff}). */
    public RayTreeSettings rayTree() {
        return rayTree;
    }

    /** How the file's PNG is encoded ({@code image.encoding}). */
    public DisplayEncoding encoding() {
        return encoding;
    }

    /** Whether the file has an {@code animation} section. */
    public boolean animated() {
        return animation != null;
    }

    /** The number of frames: the animation's, 1 for a still. */
    public int frames() {
        return animation == null ? 1 : animation.frames();
    }

    /** Frames per second: the animation's, or its default for a still. */
    public double fps() {
        return animation == null ? Animation.DEFAULT_FPS : animation.fps();
    }

    /** The name in messages: the file's path as given. */
    public String name() {
        return source.name();
    }

    /**
     * The scene at frame {@code frame} (0 to {@link #frames} - 1), not yet prepared: a new world
     * with the frame's camera and object transforms, the meshes and images shared with every other
     * frame. The report holds what this load found; a mesh read for an earlier frame is not read
     * again, nor reported again. Safe to call from several threads (one load at a time).
     */
    public synchronized LoadedScene load(int frame) throws SceneException {
        if (frame < 0 || frame >= frames()) {
            throw new IllegalArgumentException("frame " + frame + " is not one of the scene's frames, 0 to " + (frames() - 1));
        }
        String when = animation == null ? "" : " at frame " + frame;
        LoadReport report = new LoadReport();
        if (file != null) {
            report.addInput(file);
        }
        Node cameraNode = animation == null ? scene.raw("camera") : animation.camera(source, scene.raw("camera"), frame);
        Camera camera;
        try {
            camera = cameraNode != null ? CameraReader.read(source, cameraNode) : CameraReader.defaultCamera();
        } catch (SceneException e) {
            // the frame's camera is the file's with the animated values: a bad one says which frame
            throw animation == null ? e : new SceneException(e.getMessage() + " (the camera" + when + ")");
        }
        World world = new World(viewPlane, camera, SettingsReader.readAmbient(source, scene));
        TextureReader textures = new TextureReader(source, report, images);
        world.setBackground(scene.color("background", RGBColor.BLACK));
        if (scene.has("environment")) {
            world.setBackground(textures.environment(scene.raw("environment"), "environment"));
            if (scene.has("background")) {
                report.addWarning(source.at(scene.raw("background")) + ": 'background' is not used: the 'environment' map is "
                                  + "what rays that miss every object see");
            }
        }
        Map<String, Material> materials = MaterialReader.readAll(source, scene, textures);
        boolean areaLights = false;
        for (Node node : scene.list("lights")) {
            Light light = LightReader.read(source, node, world, areaLightSamples);
            areaLights |= light.hasExtent();
            world.addLight(light);
        }
        world.setTracer(SettingsReader.readTracer(source, scene, areaLights));
        if (!scene.has("objects")) {
            throw source.error(root, "the scene has no 'objects' list");
        }
        List<Node> objects = scene.list("objects");
        if (objects.isEmpty()) {
            report.addWarning(source.at(scene.raw("objects")) + ": the scene has no objects; the image shows only the background");
        }
        MeshReader meshReader = new MeshReader(cache, meshes);
        for (Node object : objects) {
            String name = ObjectReader.name(source, object);
            Matrix4 motion = animation == null ? null : animation.transform(name, frame);
            Node motionNode = motion == null ? null : animation.objectNodes().get(name);
            world.addObject(ObjectReader.read(source, object, materials, report, textures, meshReader, motion, motionNode, when));
        }
        meshReader.reportSharing(report);
        return new LoadedScene(world, rayTree, encoding, report);
    }
}

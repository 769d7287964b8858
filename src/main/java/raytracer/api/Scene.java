package raytracer.api;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import raytracer.image.DisplayEncoding;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneFile;
import raytracer.render.Workers;

/**
 * The one place where a scene file and a render's options become a scene to render, for the
 * command line and a render farm alike: the file read once ({@link SceneFile}), its image settings
 * with the options applied ({@link #image}, nothing built), and each frame loaded with them
 * ({@link #load}) and then prepared ({@link SceneFrame#prepare}) for its view.
 */
public final class Scene {
    /** The scene rendered when none is named, packed into the jar from scenes/default.yaml. */
    public static final String DEFAULT_RESOURCE = "/raytracer/scenes/default.yaml";

    private final SceneFile file;
    private final SceneOptions options;
    private final ImageSettings image;

    private Scene(SceneFile file, SceneOptions options) {
        this.file = file;
        this.options = options;
        DisplayEncoding encoding = options.encoding(file.encoding());
        // the file's codes: the cost view's false colour is written at exposure 1 through the sRGB curve
        double exposure = options.costView() ? 1 : file.viewPlane().exposure();
        boolean srgb = options.costView() || encoding.srgbCurve();
        this.image = new ImageSettings(options.viewPlane(file.viewPlane()), exposure, srgb, file.frames(), file.fps());
    }

    /** Reads the scene file {@code file}, or the embedded default scene when it is null. */
    public static Scene open(Path file, SceneOptions options) throws SceneException, IOException {
        if (file == null) {
            return new Scene(SceneFile.of("default scene", defaultSceneText(), options.areaLightSamples()), options);
        }
        return new Scene(SceneFile.read(file, options.openMeshCache(), options.areaLightSamples()), options);
    }

    /**
     * The scene file {@code file} whose text was read elsewhere ({@code text}: a render farm's
     * driver sends it to its workers, which find the meshes and images relative to {@code file}).
     */
    public static Scene of(Path file, String text, SceneOptions options) throws SceneException {
        return new Scene(file == null ? SceneFile.of("default scene", text, options.areaLightSamples())
                         : SceneFile.of(file, text, options.openMeshCache(), options.areaLightSamples()), options);
    }

    /** The embedded default scene's text. */
    public static String defaultSceneText() throws IOException {
        try (InputStream in = Scene.class.getResourceAsStream(DEFAULT_RESOURCE)) {
            if (in == null) {
                throw new IOException("the embedded default scene is missing from the jar");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    public SceneFile file() {
        return file;
    }

    public SceneOptions options() {
        return options;
    }

    /** The image every frame has, as the options change the file's: read without loading a mesh. */
    public ImageSettings image() {
        return image;
    }

    /**
     * Frame {@code frame} (0 for a still) loaded on {@code workers} (an OBJ parse forks onto them)
     * with the options applied, ready to be prepared.
     */
    public SceneFrame load(int frame, Workers workers) throws Exception {
        long start = System.nanoTime();
        LoadedScene loaded = workers.call(() -> file.load(frame));
        return new SceneFrame(frame, loaded, options, image, System.nanoTime() - start);
    }
}

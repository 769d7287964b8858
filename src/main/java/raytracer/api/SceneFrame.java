package raytracer.api;

import raytracer.accel.Aggregation;
import raytracer.core.RayTreeSettings;
import raytracer.core.World;
import raytracer.io.scene.LoadReport;
import raytracer.io.scene.LoadedScene;
import raytracer.render.Renderer;
import raytracer.render.SceneAnalysis;
import raytracer.render.Workers;
import raytracer.tracers.BvhCost;

/**
 * One frame of a {@link Scene}: its world loaded with the options applied, then prepared for its
 * view (the scene analysis, unless the options turn it off, and the search structures), and its
 * renderer. A frame serves one render of its view: the next frame is loaded anew.
 */
public final class SceneFrame {
    private final int number;
    private final LoadedScene loaded;
    private final SceneOptions options;
    private final ImageSettings image;
    private final RayTreeSettings rayTree;
    private final long loadNanos;
    private SceneAnalysis analysis;
    private long prepareNanos = -1;

    SceneFrame(int number, LoadedScene loaded, SceneOptions options, ImageSettings image, long loadNanos) {
        this.number = number;
        this.loaded = loaded;
        this.options = options;
        this.image = image;
        this.rayTree = options.rayTree(loaded.rayTree());
        this.loadNanos = loadNanos;
        loaded.world().setViewPlane(image.viewPlane());
    }

    /**
     * Analyses the world for this view (unless --no-skip or the cost view, which show the scene as
     * given), then prepares it on {@code workers}: meshes built or read from the mesh cache, the
     * objects organised for searching. The cost view then traces with {@link BvhCost}.
     */
    public void prepare(Workers workers) throws Exception {
        long start = System.nanoTime();
        World world = loaded.world();
        // the cost view shows the search structure as the scene gives it, and --no-skip renders the
        // scene as given: without the analysis nothing is left out (the image is the same; --no-skip checks it)
        analysis = options.costView() || !options.analyse() ? null : SceneAnalysis.apply(world, rayTree);
        workers.call(() -> {
            world.prepare(objects -> Aggregation.organize(objects, options.accelMode()));
            return null;
        });
        if (options.costView()) {
            world.setTracer(BvhCost::new);
        }
        prepareNanos = System.nanoTime() - start;
    }

    /** The renderer of this prepared frame on {@code workers}. */
    public Renderer renderer(Workers workers) {
        if (prepareNanos < 0) {
            throw new IllegalStateException("frame " + number + " is rendered before it is prepared");
        }
        return new Renderer(loaded.world(), rayTree, workers, options.seed());
    }

    public int number() {
        return number;
    }

    public World world() {
        return loaded.world();
    }

    /** How much of the ray tree this frame traces: the scene's, with the options applied. */
    public RayTreeSettings rayTree() {
        return rayTree;
    }

    public ImageSettings image() {
        return image;
    }

    /** What loading (and preparing, once done) found: timings, figures, warnings, the files read. */
    public LoadReport report() {
        return loaded.report();
    }

    /** What the scene analysis left out, or null when it did not run. */
    public SceneAnalysis analysis() {
        return analysis;
    }

    public long loadNanos() {
        return loadNanos;
    }

    public long prepareNanos() {
        return prepareNanos;
    }
}

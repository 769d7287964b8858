package raytracer.render;

import java.util.List;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreeSettings;
import raytracer.core.SampleTables;
import raytracer.core.ShadeRecSupply;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.math.MutableRgb;
import raytracer.math.Ray;

/**
 * Renders a prepared {@link World} on the run's {@link Workers}: the book's render loop
 * ({@link #renderPixel}, Suffern's listing 4.2) over the image's pixels, tile by tile. Around it,
 * each in a class of its own: the tiles' order ({@link TileOrder}) and fork/join split
 * ({@link TileRange}), what the tile tasks share ({@link RenderFrame}), the camera rays
 * ({@link CameraRays}) and the pixel filter ({@link BoxAverage}, the book's; {@link FilteredTile}).
 * Every sample value is a function of (seed, pixel, sample index, dimension), so the pixels depend
 * neither on the thread count nor on whether tiles are rendered together or apart ({@link #renderTiles}).
 */
public final class Renderer {
    public static final int TILE_SIZE = 32;

    private final World world;
    private final RayTreeSettings rayTree;
    private final Workers workers;
    private final long seed;
    private final ShadeRecSupply shadeRecs;
    private final CameraRays cameraRays;
    /** The render's sample sets, made again if the view plane's sampler or sample count changes. */
    private SampleTables tables;
    /** The render under way, for progress reports; null before the first. */
    private volatile RenderFrame current;

    /** Renders {@code world}, tracing as much of each ray tree as {@code rayTree} asks, on {@code workers}. */
    public Renderer(World world, RayTreeSettings rayTree, Workers workers, long seed) {
        this(world, rayTree, workers, seed, ShadeRecSupply.REUSE);
    }

    /** As above, with the workers' hit records from {@code shadeRecs} (the allocation study's alternative). */
    public Renderer(World world, RayTreeSettings rayTree, Workers workers, long seed, ShadeRecSupply shadeRecs) {
        this.world = world;
        this.rayTree = rayTree;
        this.workers = workers;
        this.seed = seed;
        this.shadeRecs = shadeRecs;
        this.cameraRays = new CameraRays(world);
        tables();
    }

    private SampleTables tables() {
        ViewPlane vp = world.viewPlane();
        SampleTables t = tables;
        if (t == null || t.sampler() != vp.sampler() || t.spp() != vp.numSamples()) {
            t = new SampleTables(vp.sampler(), vp.numSamples(), seed);
            tables = t;
        }
        return t;
    }

    /** Fraction of pixels finished, for progress reports from another thread. */
    public double progress() {
        RenderFrame frame = current;
        return frame == null ? 0 : frame.progress();
    }

    /** Renders the whole image into {@code film} and returns what it cost. */
    public RenderStats render(Film film) {
        return render(film, null);
    }

    /**
     * As {@link #render(Film)}, telling {@code listener} (if not null) of each tile as it finishes,
     * on the worker that rendered it. Under a filter wider than a pixel the film then holds each
     * finished tile's estimate from its own samples until the end, when every pixel is resolved as
     * without a listener: the image is the same.
     */
    public RenderStats render(Film film, TileListener listener) {
        long start = System.nanoTime();
        RenderFrame frame = start(film, null, listener);
        // the richest tiles first, so that the JIT profiles the traversal on rays that enter the scene's trees
        frame.run(workers, TileOrder.warmUpFirst(frame.tiles, frame.tileObjects, world.searched().size(), TILE_SIZE), this);
        if (frame.filtered != null) {
            FilteredImage.resolve(frame.filtered, film, frame.filter.reach());
        }
        return frame.stats(world.viewPlane(), workers.threads(), System.nanoTime() - start);
    }

    /** The image's tiles (x0, y0, x1, y1) in the list's order, which {@link #renderTiles} takes indices into. */
    public static List<int[]> tiles(int width, int height) {
        return TileOrder.tiles(width, height);
    }

    /**
     * Renders tiles {@code indices} of the image's list ({@link #tiles}) into arrays, for an image
     * rendered in parts (on other machines): each tile's pixels, or a wider filter's sums, which
     * {@link TileImage#assemble} makes into the image, the same to the bit as {@link #render(Film)}.
     */
    public RenderedTiles renderTiles(int[] indices) {
        ViewPlane vp = world.viewPlane();
        TileOrder.checkIndices(indices, TileOrder.tiles(vp.hres(), vp.vres()), vp.hres(), vp.vres());
        long start = System.nanoTime();
        RenderFrame frame = start(null, indices, null);
        frame.run(workers, indices, this);
        return new RenderedTiles(frame.tilePixels(indices), frame.stats(vp, workers.threads(), System.nanoTime() - start));
    }

    /** A render's shared state, its sample sets made first if the view plane changed since. */
    private RenderFrame start(Film film, int[] indices, TileListener listener) {
        tables();
        ViewPlane vp = world.viewPlane();
        FilteredImage.check(vp.filter());
        current = new RenderFrame(world, rayTree, shadeRecs, TileOrder.tiles(vp.hres(), vp.vres()), film, indices, listener);
        return current;
    }

    /**
     * Suffern's render loop (listing 4.2) for pixel (x, y): a camera ray through each of its
     * samples, traced, and its radiance handed to {@code pixel}, which averages them (the book's
     * box filter) or spreads each over the pixels a wider filter reaches. Every value a sample
     * draws, from its place in the pixel to its last light sample, is a function of (seed, pixel,
     * sample index, dimension) alone ({@link PixelSamples}).
     */
    void renderPixel(int x, int y, WorkerScratch s, PixelSink pixel) {
        Tracer tracer = world.tracer();
        int n = world.viewPlane().numSamples();
        MutableRgb L = s.color(0);
        s.samples.startPixel(tables(), x, y);
        pixel.startPixel(x, y);
        for (int j = 0; j < n; j++) {
            Ray ray = cameraRays.ray(x, y, j, n, s);
            s.startSample(j);
            tracer.traceRay(ray, 0, s, L);
            pixel.add(cameraRays.u(j, s), cameraRays.v(j, s), s.finite(L));
        }
        pixel.endPixel();
    }
}

package raytracer.render;

import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import raytracer.core.GeometricObject;
import raytracer.core.PixelFilter;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreeSettings;
import raytracer.core.SampleTables;
import raytracer.core.ShadeRecSupply;
import raytracer.core.Skipped;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.math.MutableRgb;
import raytracer.math.Ray;

/**
 * Renders a prepared {@link World} on the run's {@link Workers}: the book's render loop
 * ({@link #renderPixel}, Suffern's listing 4.2) run over the image's pixels, tile by tile. Around
 * it, each in a class of its own: the tiles' order ({@link TileOrder}) and their fork/join split
 * ({@link TileRange}), the camera rays made a block ahead of tracing ({@link CameraRays}), and the
 * pixel filter that takes the samples ({@link BoxAverage}, the book's; {@link FilteredTile} and
 * {@link FilteredImage}, a wider one). Each worker thread keeps one {@link WorkerScratch}. Every
 * sample value is a function of (seed, pixel, sample index, dimension), so the pixels do not
 * depend on the thread count or the order in which tiles finish, nor on whether the tiles are
 * rendered together or apart ({@link #renderTiles}, {@link TileImage}: an image rendered in parts
 * on several machines).
 */
public final class Renderer {
    public static final int TILE_SIZE = 32;

    private final World world;
    private final RayTreeSettings rayTree;
    private final Workers workers;
    private final long seed;
    /** The render's sample sets, made again if the view plane's sampler or sample count changes. */
    private SampleTables tables;
    private final ShadeRecSupply shadeRecs;
    private final CameraRays cameraRays;
    private final AtomicLong pixelsDone = new AtomicLong();
    private volatile long pixelsTotal = 1;

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
        return (double) pixelsDone.get() / pixelsTotal;
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
        tables(); // made here, before the workers start, if the view plane changed since
        ViewPlane vp = world.viewPlane();
        PixelFilter filter = vp.filter();
        FilteredImage.check(filter);
        List<int[]> tiles = TileOrder.tiles(vp.hres(), vp.vres());
        long start = System.nanoTime();
        Frame frame = frame(tiles, film, null, listener);
        run(frame, null);
        if (frame.filtered() != null) {
            FilteredImage.resolve(frame.filtered(), film, filter.reach());
        }
        return totals(vp, System.nanoTime() - start, frame.scratches());
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
        tables();
        ViewPlane vp = world.viewPlane();
        PixelFilter filter = vp.filter();
        FilteredImage.check(filter);
        List<int[]> tiles = TileOrder.tiles(vp.hres(), vp.vres());
        boolean[] given = new boolean[tiles.size()];
        for (int index : indices) {
            if (index < 0 || index >= tiles.size()) {
                throw new IllegalArgumentException("tile " + index + " is not one of the " + tiles.size() + " tiles of a "
                                                   + vp.hres() + "x" + vp.vres() + " image");
            }
            if (given[index]) {
                // two workers would render it into one tile's arrays at once
                throw new IllegalArgumentException("tile " + index + " is given twice");
            }
            given[index] = true;
        }
        long start = System.nanoTime();
        Frame frame = frame(tiles, null, indices, null);
        run(frame, indices);
        TilePixels[] out = new TilePixels[indices.length];
        for (int k = 0; k < indices.length; k++) {
            int i = indices[k];
            int[] t = tiles.get(i);
            out[k] = frame.filtered() != null ? TilePixels.filtered(i, t[0], t[1], t[2], t[3], frame.filtered()[i].sums())
                : TilePixels.box(i, t[0], t[1], t[2], t[3], pixels(frame.tileFilms()[i]));
        }
        return new RenderedTiles(out, totals(vp, System.nanoTime() - start, frame.scratches()));
    }

    /** A tile's own film as three floats a pixel, row by row. */
    private static float[] pixels(Film film) {
        float[] rgb = new float[3 * film.width() * film.height()];
        for (int y = 0, i = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    rgb[i++] = film.get(x, y, c);
                }
            }
        }
        return rgb;
    }

    /**
     * The render of {@code tiles} into {@code film}, or (null film) each tile into arrays of its
     * own; {@code indices} (null: all) are the tiles rendered, for which the camera rays' objects
     * are found.
     */
    private Frame frame(List<int[]> tiles, Film film, int[] indices, TileListener listener) {
        PixelFilter filter = world.viewPlane().filter();
        int rendered = indices == null ? tiles.size() : indices.length;
        long pixels = 0;
        for (int k = 0; k < rendered; k++) {
            int[] tile = tiles.get(indices == null ? k : indices[k]);
            pixels += (long) (tile[2] - tile[0]) * (tile[3] - tile[1]);
        }
        pixelsTotal = pixels;
        pixelsDone.set(0);
        Queue<WorkerScratch> scratches = new ConcurrentLinkedQueue<>();
        ThreadLocal<WorkerScratch> scratch = ThreadLocal.withInitial(() -> {
            WorkerScratch s = new WorkerScratch(world, rayTree, shadeRecs);
            scratches.add(s);
            return s;
        });
        return new Frame(tiles, film, filter, scratch, scratches, filter.isBox() ? null : new FilteredTile[tiles.size()],
                         filter.isBox() && film == null ? new Film[tiles.size()] : null, TileObjects.of(world, tiles, indices), listener);
    }

    /**
     * Renders tiles {@code indices} of the frame's list on the workers, or (null) all of them with
     * the richest first ({@link TileOrder#warmUpFirst}), so that the JIT profiles the traversal on
     * rays that enter the scene's trees. A wider filter's sums are added in the list's order
     * whatever the order rendered, so the image does not depend on it.
     */
    private void run(Frame frame, int[] indices) {
        int[] order = indices != null ? indices
            : TileOrder.warmUpFirst(frame.tiles(), frame.tileObjects(), world.searched().size(), TILE_SIZE);
        workers.invoke(new TileRange(k -> renderTile(frame, order[k]), 0, order.length));
    }

    /**
     * What the tasks of one render share: the tile list, the film, the filter, each worker's
     * scratch, and per tile its filtered sums (null under the box filter, whose pixels go straight
     * to the film), or, for tiles rendered apart, its own film (null when there is one film), and
     * the objects its camera rays can hit ({@link TileObjects}; null when the world is not
     * searched by tile); and who is told of finished tiles (a preview; null for none).
     */
    private record Frame(List<int[]> tiles, Film film, PixelFilter filter, ThreadLocal<WorkerScratch> scratch,
                         Queue<WorkerScratch> scratches, FilteredTile[] filtered, Film[] tileFilms, GeometricObject[][] tileObjects,
                         TileListener listener) {

        /** Where the samples of tile {@code index} go: the box filter's averages, or the tile's new sums. */
        PixelSink pixels(int index) {
            int[] tile = tiles.get(index);
            if (filtered == null) {
                if (tileFilms == null) {
                    return new BoxAverage(film);
                }
                Film own = new Film(tile[2] - tile[0], tile[3] - tile[1]);
                tileFilms[index] = own;
                return new BoxAverage(own, tile[0], tile[1]);
            }
            FilteredTile sums = new FilteredTile(filter, tile[0], tile[1], tile[2], tile[3]);
            filtered[index] = sums;
            return sums;
        }
    }

    /**
     * Renders tile {@code index} of the frame's list on the calling worker, row by row, counting its
     * pixels, and tells the frame's listener (if any) once its pixels are in the film.
     */
    private void renderTile(Frame frame, int index) {
        int[] tile = frame.tiles().get(index);
        WorkerScratch s = frame.scratch().get();
        s.cameraRayObjects = frame.tileObjects() == null ? null : frame.tileObjects()[index];
        PixelSink pixels = frame.pixels(index);
        for (int y = tile[1]; y < tile[3]; y++) {
            for (int x = tile[0]; x < tile[2]; x++) {
                renderPixel(x, y, s, pixels);
            }
            pixelsDone.addAndGet(tile[2] - tile[0]);
        }
        if (frame.listener() != null) {
            if (frame.filtered() != null) {
                frame.filtered()[index].estimate(frame.film());
            }
            frame.listener().tileDone(tile[0], tile[1], tile[2], tile[3]);
        }
    }

    /**
     * Suffern's render loop (listing 4.2) for pixel (x, y): a camera ray through each of its
     * samples, traced, and its radiance handed to {@code pixel}, which averages them (the book's
     * box filter) or spreads each over the pixels a wider filter reaches. Every value a sample
     * draws, from its place in the pixel to its last light sample, is a function of (seed, pixel,
     * sample index, dimension) alone ({@link PixelSamples}); the camera rays are made a block ahead
     * of tracing ({@link CameraRays}).
     */
    void renderPixel(int x, int y, WorkerScratch s, PixelSink pixel) {
        Tracer tracer = world.tracer();
        int n = world.viewPlane().numSamples();
        MutableRgb L = s.color(0);
        s.samples.startPixel(tables(), x, y);
        pixel.startPixel(x, y);
        for (int j = 0; j < n; j++) {
            Ray ray = cameraRays.ray(x, y, j, n, s);
            startSample(j, s);
            tracer.traceRay(ray, 0, s, L);
            pixel.add(cameraRays.u(j, s), cameraRays.v(j, s), finite(L, s));
        }
        pixel.endPixel();
    }

    /** Starts sample {@code j}'s values, reseeds the worker's free generator from them, and counts its camera ray. */
    private static void startSample(int j, WorkerScratch s) {
        s.samples.startSample(j);
        s.rng.reseed(s.samples.sampleKey(j));
        s.primaryRays++;
    }

    /**
     * {@code L}, or black when it came out NaN or infinite: such a sample is counted and reported
     * (a defect to fix, never a pixel to show) and weighs as a black one.
     */
    private static MutableRgb finite(MutableRgb L, WorkerScratch s) {
        if (!(Double.isFinite(L.r) && Double.isFinite(L.g) && Double.isFinite(L.b))) {
            s.nonFiniteSamples++;
            L.setBlack();
        }
        return L;
    }

    /** The render's figures: the workers' counts summed. */
    private RenderStats totals(ViewPlane vp, long wallNanos, Queue<WorkerScratch> scratches) {
        long primary = 0;
        long secondary = 0;
        long shadow = 0;
        long nonFinite = 0;
        long boxTests = 0;
        long[] skipped = new long[Skipped.KINDS];
        for (WorkerScratch s : scratches) {
            for (int k = 0; k < Skipped.KINDS; k++) {
                skipped[k] += s.skipped[k];
            }
            boxTests += s.boxTests();
            primary += s.primaryRays;
            secondary += s.secondaryRays;
            shadow += s.shadowRays;
            nonFinite += s.nonFiniteSamples;
        }
        return new RenderStats(vp.hres(), vp.vres(), vp.numSamples(), workers.threads(), wallNanos,
                               primary, secondary, shadow, nonFinite, boxTests, skipped);
    }
}

package raytracer.render;

import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.RecursiveAction;
import java.util.concurrent.atomic.AtomicLong;
import raytracer.core.Camera;
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
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.SampleMapping;
import raytracer.math.MutableVec3;

/**
 * Renders a prepared {@link World} on the run's {@link Workers}: the image is cut into square tiles,
 * the tile list is split in halves until one tile remains per task, and each worker thread keeps one
 * {@link WorkerScratch}. Every sample value is a function of (seed, pixel, sample index, dimension),
 * so the pixels do not depend on the thread count or the order in which tiles finish.
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
    private final AtomicLong pixelsDone = new AtomicLong();
    private volatile long pixelsTotal = 1;
    /** Told of each finished tile during {@link #render(Film, TileListener)}; null for none. */
    private TileListener tileListener;

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
     * As {@link #render(Film)}, telling {@code listener} (if not null) of each tile as it finishes.
     * Under a filter wider than a pixel the film then holds each finished tile's estimate from its
     * own samples until the end, when every pixel is resolved as without a listener: the image is
     * the same.
     */
    public RenderStats render(Film film, TileListener listener) {
        tileListener = listener; // seen by the workers: the pool's invoke happens after this write
        tables(); // made here, before the workers start, if the view plane changed since
        ViewPlane vp = world.viewPlane();
        List<int[]> tiles = tiles(vp.hres(), vp.vres());
        pixelsTotal = (long) vp.hres() * vp.vres();
        pixelsDone.set(0);
        Queue<WorkerScratch> scratches = new ConcurrentLinkedQueue<>();
        ThreadLocal<WorkerScratch> scratch = ThreadLocal.withInitial(() -> {
            WorkerScratch s = new WorkerScratch(world, rayTree, shadeRecs);
            scratches.add(s);
            return s;
        });
        PixelFilter filter = vp.filter();
        checkFilter(filter);
        FilteredTile[] filtered = filter.isBox() ? null : new FilteredTile[tiles.size()];
        long start = System.nanoTime();
        GeometricObject[][] tileObjects = TileObjects.of(world, tiles);
        int[] order = TileOrder.warmUpFirst(tiles, tileObjects, world.searched().size(), TILE_SIZE);
        workers.invoke(new TileRange(tiles, order, 0, order.length, film, scratch, filtered, tileObjects));
        if (filtered != null) {
            resolve(filtered, film, filter.reach());
        }
        long wall = System.nanoTime() - start;
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
        return new RenderStats(vp.hres(), vp.vres(), vp.numSamples(), workers.threads(), wall,
                               primary, secondary, shadow, nonFinite, boxTests, skipped);
    }

    /**
     * The tiles (x0, y0, x1, y1) of a width x height image, spread over it by bit reversal
     * ({@link TileOrder#spread}): the order in which a wide filter's sums are added, and the order
     * of rendering but for the richest tiles first ({@link TileOrder#warmUpFirst}).
     */
    static List<int[]> tiles(int width, int height) {
        return TileOrder.spread(width, height, TILE_SIZE);
    }

    /**
     * Refuses, before any ray is traced, a filter that {@link #resolve} cannot gather: one whose
     * radius does not pass a pixel's half width (a sample at its pixel's edge could weigh nothing,
     * and a pixel all of whose samples did would be 0 / 0), or reaches past half a tile (a pixel
     * would then lie in the margins of more than two tiles along an axis).
     */
    private static void checkFilter(PixelFilter filter) {
        if (filter.isBox()) {
            return;
        }
        if (!(filter.radius() > 0.5) || filter.reach() > TILE_SIZE / 2) {
            throw new IllegalArgumentException("the " + filter.name() + " filter's radius must be above 0.5 and below "
                                               + (TILE_SIZE / 2 + 0.5) + " pixels, got " + filter.radius());
        }
    }

    /**
     * Makes each pixel the weighted average of the samples that reached it: the sums of the tiles
     * whose margins hold it (its own and at most three neighbours, since the reach is at most half
     * a tile: at most two tiles along each axis), added in the order of the tile list, then divided
     * by the summed weight (which is positive, since the radius passes a pixel's half width, so
     * the pixel's own samples weigh something). Pixel by pixel, so no image of sums is held beside
     * the tiles'.
     */
    private static void resolve(FilteredTile[] filtered, Film film, int reach) {
        int width = film.width();
        int height = film.height();
        int columns = (width + TILE_SIZE - 1) / TILE_SIZE;
        int rows = (height + TILE_SIZE - 1) / TILE_SIZE;
        // each tile's place in the list, by its place in the grid of tiles
        int[] listIndex = new int[columns * rows];
        for (int i = 0; i < filtered.length; i++) {
            listIndex[filtered[i].y0() / TILE_SIZE * columns + filtered[i].x0() / TILE_SIZE] = i;
        }
        int[] near = new int[4];
        double[] acc = new double[4];
        for (int y = 0; y < height; y++) {
            int row0 = Math.max(0, y - reach) / TILE_SIZE;
            int row1 = Math.min(height - 1, y + reach) / TILE_SIZE;
            for (int x = 0; x < width; x++) {
                int column0 = Math.max(0, x - reach) / TILE_SIZE;
                int column1 = Math.min(width - 1, x + reach) / TILE_SIZE;
                int n = 0;
                for (int row = row0; row <= row1; row++) {
                    for (int column = column0; column <= column1; column++) {
                        // insertion into list order
                        int index = listIndex[row * columns + column];
                        int k = n++;
                        while (k > 0 && near[k - 1] > index) {
                            near[k] = near[k - 1];
                            k--;
                        }
                        near[k] = index;
                    }
                }
                acc[0] = 0;
                acc[1] = 0;
                acc[2] = 0;
                acc[3] = 0;
                for (int k = 0; k < n; k++) {
                    filtered[near[k]].addSums(x, y, acc);
                }
                film.set(x, y, acc[0] / acc[3], acc[1] / acc[3], acc[2] / acc[3]);
            }
        }
    }

    /** Splits a range of the render order in halves; a single tile is rendered in place. */
    private final class TileRange extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient List<int[]> tiles;
        /** Positions in {@link #tiles} in the order of rendering. */
        private final transient int[] order;
        private final int from;
        private final int to;
        private final transient Film film;
        private final transient ThreadLocal<WorkerScratch> scratch;
        /** Per tile, its filtered sums; null for the box filter, whose pixels go straight to the film. */
        private final transient FilteredTile[] filtered;
        /** Per tile, the objects its camera rays can hit ({@link TileObjects}); null when not searched by tile. */
        private final transient GeometricObject[][] tileObjects;

        TileRange(List<int[]> tiles, int[] order, int from, int to, Film film, ThreadLocal<WorkerScratch> scratch,
                  FilteredTile[] filtered, GeometricObject[][] tileObjects) {
            this.tiles = tiles;
            this.order = order;
            this.from = from;
            this.to = to;
            this.film = film;
            this.scratch = scratch;
            this.filtered = filtered;
            this.tileObjects = tileObjects;
        }

        @Override
        protected void compute() {
            if (to - from > 1) {
                int mid = (from + to) >>> 1;
                invokeAll(new TileRange(tiles, order, from, mid, film, scratch, filtered, tileObjects),
                          new TileRange(tiles, order, mid, to, film, scratch, filtered, tileObjects));
                return;
            }
            int index = order[from];
            int[] tile = tiles.get(index);
            WorkerScratch s = scratch.get();
            s.cameraRayObjects = tileObjects == null ? null : tileObjects[index];
            FilteredTile sums = null;
            if (filtered != null) {
                sums = new FilteredTile(world.viewPlane().filter(), tile[0], tile[1], tile[2], tile[3]);
                filtered[index] = sums;
            }
            for (int y = tile[1]; y < tile[3]; y++) {
                for (int x = tile[0]; x < tile[2]; x++) {
                    renderPixel(x, y, s, film, sums);
                }
                pixelsDone.addAndGet(tile[2] - tile[0]);
            }
            if (tileListener != null) {
                if (sums != null) {
                    sums.estimate(film);
                }
                tileListener.tileDone(tile[0], tile[1], tile[2], tile[3]);
            }
        }
    }

    /**
     * Averages the samples of pixel (x, y) (Suffern, listing 4.2). Each sample's values, from its
     * position in the pixel to its last light sample, are functions of (seed, pixel, sample index,
     * dimension) alone ({@link PixelSamples}), so the camera rays of up to
     * {@link WorkerScratch#CAMERA_RAYS} samples are made before the first of them is traced: they
     * depend on nothing traced, and made in one loop, one ray's table reads, square root and
     * divisions overlap another's, where one sample at a time they headed its chain of dependent
     * arithmetic and the processor waited on them. Under the box filter the average goes to
     * {@code film}; under a wider one each sample goes to {@code filtered}, the tile's sums.
     */
    void renderPixel(int x, int y, WorkerScratch s, Film film, FilteredTile filtered) {
        ViewPlane vp = world.viewPlane();
        Camera camera = world.camera();
        Tracer tracer = world.tracer();
        boolean lens = camera.needsLensSamples();
        PixelSamples samples = s.samples;
        int n = vp.numSamples();
        samples.startPixel(tables(), x, y);
        MutableRgb sample = s.color(0);
        MutableVec3 disk = s.diskScratch;
        double r = 0;
        double g = 0;
        double b = 0;
        for (int first = 0; first < n; first += WorkerScratch.CAMERA_RAYS) {
            int end = Math.min(n, first + WorkerScratch.CAMERA_RAYS);
            for (int i = first; i < end; i++) {
                samples.startSample(i);
                samples.get2D(0, PixelSamples.PIXEL, 0, 1);
                s.pixelU[i - first] = samples.u;
                s.pixelV[i - first] = samples.v;
                double px = x + samples.u;
                double py = y + samples.v;
                Ray ray = s.cameraRay(i - first);
                if (lens) {
                    // the concentric map keeps the pattern's strata (Suffern, section 10.4)
                    samples.get2D(0, PixelSamples.LENS, 0, 1);
                    SampleMapping.toUnitDisk(samples.u, samples.v, disk);
                    camera.generateRay(vp, px, py, disk.x, disk.y, ray);
                } else {
                    camera.generateRay(vp, px, py, 0, 0, ray);
                }
            }
            for (int i = first; i < end; i++) {
                samples.startSample(i);
                s.rng.reseed(samples.sampleKey(i));
                s.primaryRays++;
                tracer.traceRay(s.cameraRay(i - first), 0, s, sample);
                boolean finite = Double.isFinite(sample.r) && Double.isFinite(sample.g) && Double.isFinite(sample.b);
                if (filtered != null) {
                    if (finite) {
                        filtered.add(x, y, s.pixelU[i - first], s.pixelV[i - first], sample.r, sample.g, sample.b);
                    } else {
                        filtered.addBlack(x, y, s.pixelU[i - first], s.pixelV[i - first]);
                        s.nonFiniteSamples++;
                    }
                } else if (finite) {
                    r += sample.r;
                    g += sample.g;
                    b += sample.b;
                } else {
                    s.nonFiniteSamples++; // counted and reported: a defect to fix, never a pixel to show
                }
            }
        }
        if (filtered == null) {
            film.set(x, y, r / n, g / n, b / n);
        }
    }
}

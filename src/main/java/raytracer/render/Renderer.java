package raytracer.render;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.RecursiveAction;
import java.util.concurrent.atomic.AtomicLong;
import raytracer.core.Camera;
import raytracer.core.RayTreeSettings;
import raytracer.core.Sampler;
import raytracer.core.ShadeRecSupply;
import raytracer.core.Skipped;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.Rng;
import raytracer.math.SampleMapping;
import raytracer.math.MutableVec3;

/**
 * Renders a prepared {@link World} on the run's {@link Workers}: the image is cut into square tiles,
 * the tile list is split in halves until one tile remains per task, and each worker thread keeps one
 * {@link WorkerScratch}. Every pixel reseeds the worker's generator from (seed, x, y), so the pixels
 * do not depend on the thread count or the order in which tiles finish.
 */
public final class Renderer {
    public static final int TILE_SIZE = 32;

    private final World world;
    private final RayTreeSettings rayTree;
    private final Workers workers;
    private final long seed;
    private final ShadeRecSupply shadeRecs;
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
    }

    /** Fraction of pixels finished, for progress reports from another thread. */
    public double progress() {
        return (double) pixelsDone.get() / pixelsTotal;
    }

    /** Renders the whole image into {@code film} and returns what it cost. */
    public RenderStats render(Film film) {
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
        long start = System.nanoTime();
        workers.invoke(new TileRange(tiles, 0, tiles.size(), film, scratch));
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

    private static List<int[]> tiles(int width, int height) {
        List<int[]> tiles = new ArrayList<>();
        for (int y = 0; y < height; y += TILE_SIZE) {
            for (int x = 0; x < width; x += TILE_SIZE) {
                tiles.add(new int[] {x, y, Math.min(x + TILE_SIZE, width), Math.min(y + TILE_SIZE, height)});
            }
        }
        return tiles;
    }

    /** Splits a range of tiles in halves; a single tile is rendered in place. */
    private final class TileRange extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient List<int[]> tiles;
        private final int from;
        private final int to;
        private final transient Film film;
        private final transient ThreadLocal<WorkerScratch> scratch;

        TileRange(List<int[]> tiles, int from, int to, Film film, ThreadLocal<WorkerScratch> scratch) {
            this.tiles = tiles;
            this.from = from;
            this.to = to;
            this.film = film;
            this.scratch = scratch;
        }

        @Override
        protected void compute() {
            if (to - from > 1) {
                int mid = (from + to) >>> 1;
                invokeAll(new TileRange(tiles, from, mid, film, scratch), new TileRange(tiles, mid, to, film, scratch));
                return;
            }
            int[] tile = tiles.get(from);
            WorkerScratch s = scratch.get();
            for (int y = tile[1]; y < tile[3]; y++) {
                for (int x = tile[0]; x < tile[2]; x++) {
                    renderPixel(x, y, s, film);
                }
                pixelsDone.addAndGet(tile[2] - tile[0]);
            }
        }
    }

    /** Averages the samples of pixel (x, y) (Suffern, listing 4.2), seeded by the pixel alone. */
    void renderPixel(int x, int y, WorkerScratch s, Film film) {
        ViewPlane vp = world.viewPlane();
        Camera camera = world.camera();
        Tracer tracer = world.tracer();
        Sampler sampler = vp.sampler();
        int n = vp.numSamples();
        s.rng.reseed(Rng.pixelSeed(seed, x, y));
        sampler.generate(n, s.rng, s.sampleX, s.sampleY);
        if (camera.needsLensSamples()) {
            lensSamples(n, sampler, s);
        }
        Ray ray = s.ray(0);
        MutableRgb sample = s.color(0);
        double r = 0;
        double g = 0;
        double b = 0;
        for (int i = 0; i < n; i++) {
            camera.generateRay(vp, x + s.sampleX[i], y + s.sampleY[i], s.lensX[i], s.lensY[i], ray);
            s.primaryRays++;
            tracer.traceRay(ray, 0, s, sample);
            if (Double.isFinite(sample.r) && Double.isFinite(sample.g) && Double.isFinite(sample.b)) {
                r += sample.r;
                g += sample.g;
                b += sample.b;
            } else {
                s.nonFiniteSamples++; // counted and reported: a defect to fix, never a pixel to show
            }
        }
        film.set(x, y, r / n, g / n, b / n);
    }

    /**
     * Lens samples from the same pattern, shuffled so they do not correlate with the pixel samples
     * (Suffern, section 10.4), then mapped to the unit disk.
     */
    private static void lensSamples(int n, Sampler sampler, WorkerScratch s) {
        sampler.generate(n, s.rng, s.lensX, s.lensY);
        MutableVec3 disk = s.diskScratch;
        for (int i = n - 1; i >= 0; i--) {
            int j = s.rng.nextInt(i + 1);
            double lx = s.lensX[j];
            double ly = s.lensY[j];
            s.lensX[j] = s.lensX[i];
            s.lensY[j] = s.lensY[i];
            SampleMapping.toUnitDisk(lx, ly, disk);
            s.lensX[i] = disk.x;
            s.lensY[i] = disk.y;
        }
    }
}

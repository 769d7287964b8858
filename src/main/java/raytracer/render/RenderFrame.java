package raytracer.render;

import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import raytracer.core.GeometricObject;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadeRecSupply;
import raytracer.core.Skipped;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;

/**
 * What the tile tasks of one render share: the image's tile list, the film (or, for tiles
 * rendered apart on other machines, a film per tile), the pixel filter and, under a filter wider
 * than a pixel, each tile's sums; the objects each tile's camera rays can hit ({@link TileObjects});
 * one {@link WorkerScratch} per worker thread, whose counts make the render's statistics; and who
 * is told of finished tiles (a preview).
 */
final class RenderFrame {
    final List<int[]> tiles;
    final Film film;
    final PixelFilter filter;
    /** Per tile its filtered sums; null under the box filter, whose pixels go straight to a film. */
    final FilteredTile[] filtered;
    /** Per tile its own film when the tiles are rendered apart; else null. */
    final Film[] tileFilms;
    /** Per tile the objects its camera rays can hit; null when the world is not searched by tile. */
    final GeometricObject[][] tileObjects;
    /** Told of each finished tile, or null. */
    final TileListener listener;
    private final Queue<WorkerScratch> scratches = new ConcurrentLinkedQueue<>();
    private final ThreadLocal<WorkerScratch> scratch;
    private final long pixels;
    private final AtomicLong pixelsDone = new AtomicLong();

    /**
     * The render of tiles {@code indices} of {@code tiles} (null: all) into {@code film}, or (null
     * film) each into a film of its own.
     */
    RenderFrame(World world, RayTreeSettings rayTree, ShadeRecSupply shadeRecs, List<int[]> tiles, Film film, int[] indices,
                TileListener listener) {
        this.tiles = tiles;
        this.film = film;
        this.filter = world.viewPlane().filter();
        this.filtered = filter.isBox() ? null : new FilteredTile[tiles.size()];
        this.tileFilms = filter.isBox() && film == null ? new Film[tiles.size()] : null;
        this.tileObjects = TileObjects.of(world, tiles, indices);
        this.listener = listener;
        long count = 0;
        for (int k = 0; k < (indices == null ? tiles.size() : indices.length); k++) {
            int[] tile = tiles.get(indices == null ? k : indices[k]);
            count += (long) (tile[2] - tile[0]) * (tile[3] - tile[1]);
        }
        this.pixels = count;
        this.scratch = ThreadLocal.withInitial(() -> {
            WorkerScratch s = new WorkerScratch(world, rayTree, shadeRecs);
            scratches.add(s);
            return s;
        });
    }

    /**
     * Renders tiles {@code order} of the list on {@code workers}, each pixel by the book's loop of
     * {@code renderer}. A wider filter's sums are added in the list's order, whatever this one.
     */
    void run(Workers workers, int[] order, Renderer renderer) {
        workers.invoke(new TileRange(k -> renderTile(order[k], renderer), 0, order.length));
    }

    /** Renders tile {@code index} on the calling worker, row by row, and tells the listener (if any) once its pixels are in the film. */
    private void renderTile(int index, Renderer renderer) {
        int[] tile = tiles.get(index);
        WorkerScratch s = scratch.get();
        s.cameraRayObjects = tileObjects == null ? null : tileObjects[index];
        PixelSink sink = pixels(index);
        for (int y = tile[1]; y < tile[3]; y++) {
            for (int x = tile[0]; x < tile[2]; x++) {
                renderer.renderPixel(x, y, s, sink);
            }
            pixelsDone.addAndGet(tile[2] - tile[0]);
        }
        if (listener != null) {
            if (filtered != null) {
                filtered[index].estimate(film);
            }
            listener.tileDone(tile[0], tile[1], tile[2], tile[3]);
        }
    }

    /** The fraction of the frame's pixels finished. */
    double progress() {
        return (double) pixelsDone.get() / Math.max(1, pixels);
    }

    /** Where the samples of tile {@code index} go: the box filter's averages, or the tile's new sums. */
    private PixelSink pixels(int index) {
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

    /** Tiles {@code indices}' pixels as rendered apart. */
    TilePixels[] tilePixels(int[] indices) {
        TilePixels[] out = new TilePixels[indices.length];
        for (int k = 0; k < indices.length; k++) {
            out[k] = tilePixels(indices[k]);
        }
        return out;
    }

    /** Tile {@code index}'s pixels as rendered apart: its own film's, or its filtered sums. */
    private TilePixels tilePixels(int index) {
        int[] t = tiles.get(index);
        if (filtered != null) {
            return TilePixels.filtered(index, t[0], t[1], t[2], t[3], filtered[index].sums());
        }
        Film own = tileFilms[index];
        float[] rgb = new float[3 * own.width() * own.height()];
        for (int y = 0, i = 0; y < own.height(); y++) {
            for (int x = 0; x < own.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    rgb[i++] = own.get(x, y, c);
                }
            }
        }
        return TilePixels.box(index, t[0], t[1], t[2], t[3], rgb);
    }

    /** The render's figures: the workers' counts summed. */
    RenderStats stats(ViewPlane vp, int threads, long wallNanos) {
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
        return new RenderStats(vp.hres(), vp.vres(), vp.numSamples(), threads, wallNanos, primary, secondary, shadow, nonFinite,
                               boxTests, skipped);
    }
}

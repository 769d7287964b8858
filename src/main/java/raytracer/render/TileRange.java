package raytracer.render;

import java.util.concurrent.RecursiveAction;

/**
 * A range of the tile list, split in halves until one tile remains per task, which the fork/join
 * pool's worker that takes it renders ({@link Renderer}).
 */
final class TileRange extends RecursiveAction {
    private static final long serialVersionUID = 1L;

    /** Renders one tile, by its index in the list, on the calling worker thread. */
    @FunctionalInterface
    interface Job {
        void renderTile(int index);
    }

    private final transient Job job;
    private final int from;
    private final int to;

    /** Tiles {@code from} .. {@code to - 1} of the list, each rendered by {@code job}. */
    TileRange(Job job, int from, int to) {
        this.job = job;
        this.from = from;
        this.to = to;
    }

    @Override
    protected void compute() {
        if (to - from > 1) {
            int mid = (from + to) >>> 1;
            invokeAll(new TileRange(job, from, mid), new TileRange(job, mid, to));
            return;
        }
        job.renderTile(from);
    }
}

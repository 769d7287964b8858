package raytracer.render;

/**
 * Told of each tile whose pixels are in the film, for a preview that shows the image as it renders
 * (the command line's {@code --show}). Called on the worker that rendered the tile, once per tile,
 * so it must return at once: hand the tile to another thread and do the work there.
 */
@FunctionalInterface
public interface TileListener {
    /** Pixels x0 .. x1 - 1, y0 .. y1 - 1 of the film are written and visible to whoever the tile is handed to. */
    void tileDone(int x0, int y0, int x1, int y1);
}

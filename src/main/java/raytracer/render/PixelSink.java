package raytracer.render;

import raytracer.math.MutableRgb;

/**
 * Where the renderer's loop hands a pixel's samples: the book's box filter averages them into the
 * pixel ({@link BoxAverage}); a wider filter spreads each over the pixels it reaches
 * ({@link FilteredTile}). One per tile, used by one worker.
 */
interface PixelSink {

    /** Begins pixel (x, y). */
    void startPixel(int x, int y);

    /** Adds a sample of radiance {@code L} taken at (x + u, y + v) in the current pixel, 0 &lt;= u, v &lt; 1. */
    void add(double u, double v, MutableRgb L);

    /** Ends the current pixel. */
    void endPixel();
}

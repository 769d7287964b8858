package raytracer.cli.show;

/**
 * How the {@code --show} window fits an image larger than the screen: the largest size of the
 * image's shape that fits, and the reduction of 0xRRGGBB pixels to it, each shown pixel the rounded
 * mean of the image pixels it covers (whole pixels: the rows and columns a shown pixel spans are cut
 * by integer division, so the reduction is exact integer arithmetic that a test can repeat).
 */
final class ShowScale {
    private ShowScale() {
    }

    /** The shown size {width, height} of a width x height image in at most maxWidth x maxHeight. */
    static int[] fit(int width, int height, int maxWidth, int maxHeight) {
        if (width <= maxWidth && height <= maxHeight) {
            return new int[] {width, height};
        }
        double shrink = Math.max((double) width / Math.max(1, maxWidth), (double) height / Math.max(1, maxHeight));
        return new int[] {Math.max(1, Math.min(maxWidth, (int) (width / shrink))),
                          Math.max(1, Math.min(maxHeight, (int) (height / shrink)))};
    }

    /** The first image column (or row) of shown column {@code i} of {@code shown}; i = shown gives the end. */
    static int start(int i, int image, int shown) {
        return (int) ((long) i * image / shown);
    }

    /**
     * Reduces the image pixels {@code from} (width x height) to {@code to} (shownWidth x shownHeight,
     * no larger) over the shown rectangle that covers image pixels x0 .. x1 - 1, y0 .. y1 - 1;
     * returns that shown rectangle {x, y, width, height}.
     */
    static int[] reduce(int[] from, int width, int height, int[] to, int shownWidth, int shownHeight,
                        int x0, int y0, int x1, int y1) {
        int sx0 = first(x0, width, shownWidth);
        int sx1 = first(x1 - 1, width, shownWidth) + 1;
        int sy0 = first(y0, height, shownHeight);
        int sy1 = first(y1 - 1, height, shownHeight) + 1;
        for (int sy = sy0; sy < sy1; sy++) {
            int rowStart = start(sy, height, shownHeight);
            int rowEnd = start(sy + 1, height, shownHeight);
            for (int sx = sx0; sx < sx1; sx++) {
                int columnStart = start(sx, width, shownWidth);
                int columnEnd = start(sx + 1, width, shownWidth);
                long r = 0;
                long g = 0;
                long b = 0;
                for (int y = rowStart; y < rowEnd; y++) {
                    for (int x = columnStart, at = y * width + columnStart; x < columnEnd; x++, at++) {
                        int rgb = from[at];
                        r += rgb >>> 16 & 0xff;
                        g += rgb >>> 8 & 0xff;
                        b += rgb & 0xff;
                    }
                }
                long n = (long) (rowEnd - rowStart) * (columnEnd - columnStart);
                to[sy * shownWidth + sx] = (int) ((r + n / 2) / n) << 16 | (int) ((g + n / 2) / n) << 8 | (int) ((b + n / 2) / n);
            }
        }
        return new int[] {sx0, sy0, sx1 - sx0, sy1 - sy0};
    }

    /** The shown column (or row) whose span holds image column {@code x}. */
    private static int first(int x, int image, int shown) {
        int i = (int) ((long) x * shown / image);
        // start(i) <= x by the floor above, but start(i + 1) may be too: the spans are of unequal width
        while (i + 1 < shown && start(i + 1, image, shown) <= x) {
            i++;
        }
        while (i > 0 && start(i, image, shown) > x) {
            i--;
        }
        return i;
    }
}

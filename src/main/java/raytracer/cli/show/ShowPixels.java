package raytracer.cli.show;

import raytracer.image.Film;

/**
 * The pixels of the {@code --show} window, without AWT: the image's 0xRRGGBB codes at full size,
 * and the pixels shown, which are the same array when the image fits the screen and else its
 * reduction ({@link ShowScale}). Used on the window's thread only.
 */
final class ShowPixels {
    private final int width;
    private final int height;
    private final int[] codes;
    private final int shownWidth;
    private final int shownHeight;
    private final int[] shown;

    /** A width x height image shown in {@code shown}, shownWidth x shownHeight pixels (at most the image's). */
    ShowPixels(int width, int height, int shownWidth, int shownHeight, int[] shown) {
        this.width = width;
        this.height = height;
        this.shownWidth = shownWidth;
        this.shownHeight = shownHeight;
        this.shown = shown;
        this.codes = shownWidth == width && shownHeight == height ? shown : new int[width * height];
    }

    /**
     * Makes pixels x0 .. x1 - 1, y0 .. y1 - 1 from {@code film} through {@code tone}; returns the
     * shown rectangle {x, y, width, height} that changed.
     */
    int[] update(Film film, int x0, int y0, int x1, int y1, ShowTone tone) {
        for (int y = y0; y < y1; y++) {
            for (int x = x0, at = y * width + x0; x < x1; x++, at++) {
                codes[at] = tone.rgb(film, x, y);
            }
        }
        if (codes == shown) {
            return new int[] {x0, y0, x1 - x0, y1 - y0};
        }
        return ShowScale.reduce(codes, width, height, shown, shownWidth, shownHeight, x0, y0, x1, y1);
    }
}

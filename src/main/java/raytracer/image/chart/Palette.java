package raytracer.image.chart;

import java.awt.Color;

/**
 * Series colours: Okabe and Ito's palette for colour-blind readers (2008), without its yellow,
 * which is too pale on white. Past seven series the colours repeat and the markers tell them apart.
 */
final class Palette {
    private static final Color[] COLOURS = {
        new Color(0x0072B2), new Color(0xD55E00), new Color(0x009E73), new Color(0xCC79A7),
        new Color(0xE69F00), new Color(0x56B4E9), new Color(0x000000)};
    static final Color GUIDE = new Color(0x808080);

    private Palette() {
    }

    static Color colour(int series) {
        return COLOURS[series % COLOURS.length];
    }
}

package raytracer.render;

/**
 * What rendering one tile of the image's list leaves, as arrays that can travel to another machine:
 * under the box filter the tile's pixels (three floats each, row by row, as the film holds them);
 * under a wider filter the tile's weighted sums over the tile and a margin of the filter's reach
 * around it ({@link FilteredTile}), which {@link TileImage} adds up with the neighbours' in the
 * order of the list, so the image is the same to the bit as one rendered whole.
 */
public final class TilePixels {
    private final int index;
    private final int x0;
    private final int y0;
    private final int x1;
    private final int y1;
    private final float[] rgb;
    private final double[] sums;

    private TilePixels(int index, int x0, int y0, int x1, int y1, float[] rgb, double[] sums) {
        if (x1 <= x0 || y1 <= y0) {
            throw new IllegalArgumentException("tile " + index + " is empty: " + x0 + ", " + y0 + " to " + x1 + ", " + y1);
        }
        if (rgb != null && rgb.length != 3 * (x1 - x0) * (y1 - y0)) {
            throw new IllegalArgumentException("tile " + index + " has " + rgb.length + " values for " + (x1 - x0) * (y1 - y0) + " pixels");
        }
        this.index = index;
        this.x0 = x0;
        this.y0 = y0;
        this.x1 = x1;
        this.y1 = y1;
        this.rgb = rgb;
        this.sums = sums;
    }

    /** Tile {@code index} (pixels x0 .. x1 - 1, y0 .. y1 - 1) under the box filter: its pixels' linear red, green, blue. */
    public static TilePixels box(int index, int x0, int y0, int x1, int y1, float[] rgb) {
        return new TilePixels(index, x0, y0, x1, y1, rgb, null);
    }

    /** Tile {@code index} under a wider filter: its weighted sums with their margin ({@link #sums}). */
    public static TilePixels filtered(int index, int x0, int y0, int x1, int y1, double[] sums) {
        return new TilePixels(index, x0, y0, x1, y1, null, sums);
    }

    /** The tile's place in the image's list of tiles ({@link Renderer#tiles}). */
    public int index() {
        return index;
    }

    public int x0() {
        return x0;
    }

    public int y0() {
        return y0;
    }

    public int x1() {
        return x1;
    }

    public int y1() {
        return y1;
    }

    /** Whether this tile holds the box filter's pixels (else a wider filter's sums). */
    public boolean isBox() {
        return rgb != null;
    }

    /** Under the box filter: 3 floats per pixel, rows from the tile's top; null otherwise. */
    public float[] rgb() {
        return rgb;
    }

    /**
     * Under a wider filter: per pixel of the tile widened by the filter's reach on every side, row
     * by row, the sums of w r, w g, w b and w of the samples this tile took; null under the box.
     */
    public double[] sums() {
        return sums;
    }
}

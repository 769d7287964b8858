package raytracer.image;

/**
 * The rendered image in linear radiance, three floats per pixel, rows from the top. Each pixel is
 * written by exactly one worker, so no locking is needed.
 */
public final class Film {
    private final int width;
    private final int height;
    private final float[] rgb;

    /** The most pixels one film holds: three floats each in one Java array. */
    public static final long MAX_PIXELS = (Integer.MAX_VALUE - 8) / 3;

    public Film(int width, int height) {
        if (width < 1 || height < 1 || (long) width * height > MAX_PIXELS) {
            throw new IllegalArgumentException("an image of " + width + " x " + height + " pixels is not possible: it needs 1 to "
                                               + MAX_PIXELS + " pixels");
        }
        this.width = width;
        this.height = height;
        this.rgb = new float[3 * width * height];
    }

    public void set(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        rgb[i] = (float) r;
        rgb[i + 1] = (float) g;
        rgb[i + 2] = (float) b;
    }

    /** Channel c (0 red, 1 green, 2 blue) of pixel (x, y). */
    public float get(int x, int y, int c) {
        return rgb[3 * (y * width + x) + c];
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }
}

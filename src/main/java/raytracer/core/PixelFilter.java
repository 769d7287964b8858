package raytracer.core;

/**
 * How a pixel's value is made from the samples around it (pbrt-v3, section 7.8): a sample
 * (dx, dy) pixels from a pixel's centre counts for it with weight w(dx) w(dy), and the pixel is the
 * weighted average of every sample within the filter's radius. The book's is the box
 * ({@link #BOX}): a pixel is the plain average of the samples taken inside it (Suffern, listing
 * 4.2). Wider filters, in the package {@code filters}, let pixels share samples, so each is less
 * noisy, at the price of a softer image.
 */
public interface PixelFilter {
    /** The book's filter: each sample counts for its own pixel only, with weight 1. */
    PixelFilter BOX = new BoxFilter();

    /** The name scene files and options give it. */
    String name();

    /** Distance from a pixel's centre, along x or y, beyond which a sample weighs nothing. */
    double radius();

    /** The weight along one axis of a sample {@code d} pixels from a pixel's centre. */
    double weight(double d);

    /**
     * True for the box, whose pixels the renderer makes as plain averages of their own samples
     * (the book's listing 4.2), without weights or sums shared between tiles.
     */
    default boolean isBox() {
        return false;
    }

    /**
     * How many pixels beyond its own, each way, a sample may reach: a sample at fraction f of its
     * pixel is |k + 0.5 - f| from the centre k pixels over, which is below the radius for some f
     * exactly when |k| &lt; radius + 0.5.
     */
    default int reach() {
        return (int) Math.ceil(radius() + 0.5) - 1;
    }
}

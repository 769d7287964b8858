package raytracer.core;

import raytracer.math.Ray;

/** Turns an image-plane position into a primary ray (Suffern, chapter 8). */
public interface Camera {

    /**
     * Writes the primary ray through the image position ({@code px}, {@code py}), in pixels from the
     * top-left corner, into {@code out}. ({@code lensX}, {@code lensY}) is a point of the unit disk
     * (the renderer maps its lens samples there) for cameras with an aperture; others ignore it.
     */
    void generateRay(ViewPlane vp, double px, double py, double lensX, double lensY, Ray out);

    /** True when the camera uses lens samples, so the renderer draws them only when needed. */
    default boolean needsLensSamples() {
        return false;
    }
}

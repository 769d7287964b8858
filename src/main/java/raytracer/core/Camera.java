package raytracer.core;

import java.util.List;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
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

    /**
     * Half-spaces whose intersection holds every point that a primary ray of {@code vp} can reach
     * (the view frustum, or the view box of a parallel projection), for the scene analysis; an
     * empty list when the camera cannot tell, and then nothing is left out for being unseen.
     */
    default List<HalfSpace> viewVolume(ViewPlane vp) {
        return viewVolume(vp, 0, 0, vp.hres(), vp.vres());
    }

    /**
     * As {@link #viewVolume(ViewPlane)}, for the primary rays through the image window
     * [x0, x1] x [y0, y1] (in pixels from the top-left corner) alone: the renderer's tiles.
     */
    default List<HalfSpace> viewVolume(ViewPlane vp, double x0, double y0, double x1, double y1) {
        return List.of();
    }

    /** A box holding the origin of every primary ray of {@code vp} (the eye, the lens, the window), or null when unknown. */
    default BBox rayOrigins(ViewPlane vp) {
        return null;
    }
}

package raytracer.api;

import raytracer.core.PixelFilter;
import raytracer.core.ViewPlane;

/**
 * A render's image as the scene file and the options make it, known without loading or building
 * anything: size, samples and filter (the view plane), how the file codes it (exposure, the sRGB
 * curve), and the animation's frames and rate (1 frame for a still).
 */
public record ImageSettings(ViewPlane viewPlane, double exposure, boolean srgb, int frames, double fps) {

    public int width() {
        return viewPlane.hres();
    }

    public int height() {
        return viewPlane.vres();
    }

    public PixelFilter filter() {
        return viewPlane.filter();
    }
}

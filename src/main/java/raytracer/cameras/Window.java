package raytracer.cameras;

import raytracer.core.ViewPlane;

/**
 * An image window [x0, x1] x [y0, y1] (pixels from the top-left corner) on the image plane of a
 * camera whose frame has half-height {@code halfHeight}: its edges' coordinates along u (left,
 * right) and v (bottom, top), computed as the cameras compute a ray's, (2 px / hres - 1) h a and
 * (1 - 2 py / vres) h. A pinhole reads them as slopes, an orthographic camera as offsets.
 */
record Window(double left, double right, double bottom, double top) {

    static Window of(ViewPlane vp, double halfHeight, double x0, double y0, double x1, double y1) {
        double aspect = (double) vp.hres() / vp.vres();
        return new Window((2 * x0 / vp.hres() - 1) * halfHeight * aspect, (2 * x1 / vp.hres() - 1) * halfHeight * aspect,
                          (1 - 2 * y1 / vp.vres()) * halfHeight, (1 - 2 * y0 / vp.vres()) * halfHeight);
    }
}

package raytracer.cameras;

import java.util.List;
import raytracer.core.Camera;
import raytracer.core.ViewPlane;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/**
 * The orthographic camera (Suffern, section 3.4): parallel rays along -w, one per point of a window
 * {@code viewHeight} world units high centred on the eye.
 */
public final class Orthographic implements Camera {
    private final Basis basis;
    private final double halfHeight;

    public Orthographic(Point3D eye, Point3D lookAt, Vector3D up, double viewHeight) {
        if (!(viewHeight > 0) || !Double.isFinite(viewHeight)) {
            throw new IllegalArgumentException("orthographic view height must be positive, got " + viewHeight);
        }
        this.basis = Basis.lookAt(eye, lookAt, up);
        this.halfHeight = viewHeight / 2;
    }

    @Override
    public void generateRay(ViewPlane vp, double px, double py, double lensX, double lensY, Ray out) {
        double aspect = (double) vp.hres() / vp.vres();
        double xs = (2 * px / vp.hres() - 1) * halfHeight * aspect;
        double ys = (1 - 2 * py / vp.vres()) * halfHeight;
        Vector3D u = basis.u();
        Vector3D v = basis.v();
        Vector3D w = basis.w();
        Point3D eye = basis.eye();
        out.set(eye.x() + xs * u.x() + ys * v.x(), eye.y() + xs * u.y() + ys * v.y(),
                eye.z() + xs * u.z() + ys * v.z(), -w.x(), -w.y(), -w.z());
    }

    /** The box of parallel rays behind the window: its edges' offsets, no slope. */
    @Override
    public List<HalfSpace> viewVolume(ViewPlane vp, double x0, double y0, double x1, double y1) {
        Window window = Window.of(vp, halfHeight, x0, y0, x1, y1);
        return basis.viewVolume(window.left(), window.right(), 0, 0, window.bottom(), window.top(), 0, 0);
    }

    @Override
    public BBox rayOrigins(ViewPlane vp) {
        return basis.origins(halfHeight * vp.hres() / vp.vres(), halfHeight);
    }
}

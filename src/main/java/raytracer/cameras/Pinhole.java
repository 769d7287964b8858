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
 * The pinhole camera (Suffern, chapter 9), set by a vertical field of view instead of the book's
 * view-plane distance: the image plane sits at distance 1 with half-height tan(fov / 2).
 */
public final class Pinhole implements Camera {
    private final Basis basis;
    private final double halfHeight;

    public Pinhole(Point3D eye, Point3D lookAt, Vector3D up, double fovDegrees) {
        if (!(fovDegrees > 0 && fovDegrees < 180)) {
            throw new IllegalArgumentException("field of view must be between 0 and 180 degrees, got " + fovDegrees);
        }
        this.basis = Basis.lookAt(eye, lookAt, up);
        this.halfHeight = Math.tan(Math.toRadians(fovDegrees) / 2);
    }

    @Override
    public void generateRay(ViewPlane vp, double px, double py, double lensX, double lensY, Ray out) {
        double aspect = (double) vp.hres() / vp.vres();
        double xs = (2 * px / vp.hres() - 1) * halfHeight * aspect;
        double ys = (1 - 2 * py / vp.vres()) * halfHeight;
        Vector3D u = basis.u();
        Vector3D v = basis.v();
        Vector3D w = basis.w();
        double dx = xs * u.x() + ys * v.x() - w.x();
        double dy = xs * u.y() + ys * v.y() - w.y();
        double dz = xs * u.z() + ys * v.z() - w.z();
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        Point3D eye = basis.eye();
        out.set(eye.x(), eye.y(), eye.z(), dx * inv, dy * inv, dz * inv);
    }

    /** The frustum from the eye through the window's edges, their slopes computed as {@link #generateRay} computes a ray's. */
    @Override
    public List<HalfSpace> viewVolume(ViewPlane vp, double x0, double y0, double x1, double y1) {
        Window window = Window.of(vp, halfHeight, x0, y0, x1, y1);
        return basis.viewVolume(0, 0, window.left(), window.right(), 0, 0, window.bottom(), window.top());
    }

    @Override
    public BBox rayOrigins(ViewPlane vp) {
        return basis.origins(0, 0);
    }
}

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
 * The thin-lens camera for depth of field (Suffern, chapter 10): rays start on a disk of radius
 * {@code lensRadius} and all pass through the point where the pinhole ray meets the focal plane at
 * {@code focalDistance}, so only that plane is sharp.
 */
public final class ThinLens implements Camera {
    private final Basis basis;
    private final double halfHeight;
    private final double lensRadius;
    private final double focalDistance;

    public ThinLens(Point3D eye, Point3D lookAt, Vector3D up, double fovDegrees, double lensRadius,
                    double focalDistance) {
        if (!(fovDegrees > 0 && fovDegrees < 180)) {
            throw new IllegalArgumentException("field of view must be between 0 and 180 degrees, got " + fovDegrees);
        }
        if (!(lensRadius >= 0) || !Double.isFinite(lensRadius)) {
            throw new IllegalArgumentException("lens radius must be 0 or more, got " + lensRadius);
        }
        if (!(focalDistance > 0) || !Double.isFinite(focalDistance)) {
            throw new IllegalArgumentException("focal distance must be positive, got " + focalDistance);
        }
        this.basis = Basis.lookAt(eye, lookAt, up);
        this.halfHeight = Math.tan(Math.toRadians(fovDegrees) / 2);
        this.lensRadius = lensRadius;
        this.focalDistance = focalDistance;
    }

    @Override
    public void generateRay(ViewPlane vp, double px, double py, double lensX, double lensY, Ray out) {
        double aspect = (double) vp.hres() / vp.vres();
        // the point on the focal plane that the pinhole ray through (px, py) reaches
        double fx = (2 * px / vp.hres() - 1) * halfHeight * aspect * focalDistance;
        double fy = (1 - 2 * py / vp.vres()) * halfHeight * focalDistance;
        double lx = lensX * lensRadius;
        double ly = lensY * lensRadius;
        Vector3D u = basis.u();
        Vector3D v = basis.v();
        Vector3D w = basis.w();
        double dx = (fx - lx) * u.x() + (fy - ly) * v.x() - focalDistance * w.x();
        double dy = (fx - lx) * u.y() + (fy - ly) * v.y() - focalDistance * w.y();
        double dz = (fx - lx) * u.z() + (fy - ly) * v.z() - focalDistance * w.z();
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        Point3D eye = basis.eye();
        out.set(eye.x() + lx * u.x() + ly * v.x(), eye.y() + lx * u.y() + ly * v.y(),
                eye.z() + lx * u.z() + ly * v.z(), dx * inv, dy * inv, dz * inv);
    }

    @Override
    public boolean needsLensSamples() {
        return lensRadius > 0;
    }

    /**
     * Every ray starts within the lens radius R of the eye and passes the focal plane within the
     * window there; at depth z its sideways offset is at most R |1 - z / f| + z a
     * &lt;= R + z (a + R / f) (a the slope of the window's edge), and at least -R + z (a' - R / f)
     * on the other side, which bounds the volume by planes.
     */
    @Override
    public List<HalfSpace> viewVolume(ViewPlane vp, double x0, double y0, double x1, double y1) {
        Window window = Window.of(vp, halfHeight, x0, y0, x1, y1);
        double spread = lensRadius / focalDistance;
        return basis.viewVolume(-lensRadius, lensRadius, window.left() - spread, window.right() + spread,
                                -lensRadius, lensRadius, window.bottom() - spread, window.top() + spread);
    }

    @Override
    public BBox rayOrigins(ViewPlane vp) {
        return basis.origins(lensRadius, lensRadius);
    }
}

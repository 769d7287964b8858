package raytracer.cameras;

import raytracer.core.Camera;
import raytracer.core.ViewPlane;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/**
 * Reference solution of exercise 2 (docs/teaching.md): the spherical panoramic camera (Suffern,
 * chapter 11). The image's x runs through the azimuth lambda, its y through the elevation psi,
 * each over its field of view, and the ray leaves the eye along
 * cos(psi) sin(lambda) u + sin(psi) v - cos(psi) cos(lambda) w.
 */
public final class Spherical implements Camera {
    private final Basis basis;
    private final double lambdaMax;
    private final double psiMax;

    public Spherical(Point3D eye, Point3D lookAt, Vector3D up, double horizontalFovDegrees, double verticalFovDegrees) {
        if (!(horizontalFovDegrees > 0 && horizontalFovDegrees <= 360 && verticalFovDegrees > 0 && verticalFovDegrees <= 180)) {
            throw new IllegalArgumentException("a spherical camera sees up to 360 degrees across and 180 up, got "
                                               + horizontalFovDegrees + " by " + verticalFovDegrees);
        }
        this.basis = Basis.lookAt(eye, lookAt, up);
        this.lambdaMax = Math.toRadians(horizontalFovDegrees) / 2;
        this.psiMax = Math.toRadians(verticalFovDegrees) / 2;
    }

    @Override
    public void generateRay(ViewPlane vp, double px, double py, double lensX, double lensY, Ray out) {
        double lambda = (2 * px / vp.hres() - 1) * lambdaMax;
        double psi = (1 - 2 * py / vp.vres()) * psiMax;
        double a = Math.cos(psi) * Math.sin(lambda);
        double b = Math.sin(psi);
        double c = -Math.cos(psi) * Math.cos(lambda);
        Vector3D u = basis.u();
        Vector3D v = basis.v();
        Vector3D w = basis.w();
        Point3D eye = basis.eye();
        out.set(eye.x(), eye.y(), eye.z(), a * u.x() + b * v.x() + c * w.x(), a * u.y() + b * v.y() + c * w.y(),
                a * u.z() + b * v.z() + c * w.z());
    }
}

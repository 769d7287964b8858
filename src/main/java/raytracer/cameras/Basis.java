package raytracer.cameras;

import java.util.ArrayList;
import java.util.List;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * The camera's orthonormal frame (Suffern, section 9.2): w points from the look-at point back to
 * the eye, u to the right, v up. When up is parallel to w (looking straight up or down) another
 * up vector is used, as the book's singularity fix does.
 */
record Basis(Point3D eye, Vector3D u, Vector3D v, Vector3D w) {

    /**
     * The view volume of rays that at depth z in front of the eye (along -w) lie between
     * {@code x0 + z sx0} and {@code x1 + z sx1} along u and between {@code y0 + z sy0} and
     * {@code y1 + z sy1} along v: for q = p - eye and z = -q . w, the four faces
     * q . (u + sx1 w) &lt;= x1, q . (-u - sx0 w) &lt;= -x0, q . (v + sy1 w) &lt;= y1,
     * q . (-v - sy0 w) &lt;= -y0, and the plane of the eye, q . w &lt;= 0. A pinhole's window has
     * offsets 0 and the window's slopes; an orthographic camera's has slopes 0.
     */
    List<HalfSpace> viewVolume(double x0, double x1, double sx0, double sx1, double y0, double y1, double sy0, double sy1) {
        List<HalfSpace> faces = new ArrayList<>();
        faces.add(face(u.add(w.scale(sx1)), x1));
        faces.add(face(u.scale(-1).add(w.scale(-sx0)), -x0));
        faces.add(face(v.add(w.scale(sy1)), y1));
        faces.add(face(v.scale(-1).add(w.scale(-sy0)), -y0));
        faces.add(face(w, 0));
        return faces;
    }

    /** The box of the points eye + x u + y v with |x| &lt;= reachX, |y| &lt;= reachY, rounded outward by an ulp. */
    BBox origins(double reachX, double reachY) {
        double ex = reachX * Math.abs(u.x()) + reachY * Math.abs(v.x());
        double ey = reachX * Math.abs(u.y()) + reachY * Math.abs(v.y());
        double ez = reachX * Math.abs(u.z()) + reachY * Math.abs(v.z());
        return new BBox(Math.nextDown(eye.x() - ex), Math.nextDown(eye.y() - ey), Math.nextDown(eye.z() - ez),
                        Math.nextUp(eye.x() + ex), Math.nextUp(eye.y() + ey), Math.nextUp(eye.z() + ez));
    }

    /** n . (p - eye) &lt;= reach. */
    private HalfSpace face(Vector3D n, double reach) {
        return new HalfSpace(n.x(), n.y(), n.z(), reach + n.x() * eye.x() + n.y() * eye.y() + n.z() * eye.z(),
                             Math.max(Math.abs(eye.x()), Math.max(Math.abs(eye.y()), Math.abs(eye.z()))));
    }

    static Basis lookAt(Point3D eye, Point3D lookAt, Vector3D up) {
        Vector3D view = eye.sub(lookAt);
        // a distance whose square overflows would normalise w to zero, and every ray with it
        if (!(view.length() > 0) || !view.isFinite() || !Double.isFinite(view.length())) {
            throw new IllegalArgumentException("camera eye and look-at point must differ, be finite and lie less than 1e154 apart");
        }
        if (!(up.length() > 0) || !up.isFinite()) {
            throw new IllegalArgumentException("camera up vector must be finite and non-zero");
        }
        Vector3D w = view.normalize();
        Vector3D upUnit = up.normalize();
        if (Math.abs(upUnit.dot(w)) > 1 - 1e-9) {
            upUnit = Math.abs(w.z()) < 0.9 ? new Vector3D(0, 0, 1) : new Vector3D(1, 0, 0);
        }
        Vector3D u = upUnit.cross(w).normalize();
        Vector3D v = w.cross(u);
        return new Basis(eye, u, v, w);
    }
}

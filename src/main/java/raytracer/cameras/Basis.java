package raytracer.cameras;

import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * The camera's orthonormal frame (Suffern, section 9.2): w points from the look-at point back to
 * the eye, u to the right, v up. When up is parallel to w (looking straight up or down) another
 * up vector is used, as the book's singularity fix does.
 */
record Basis(Point3D eye, Vector3D u, Vector3D v, Vector3D w) {

    static Basis lookAt(Point3D eye, Point3D lookAt, Vector3D up) {
        Vector3D view = eye.sub(lookAt);
        if (!(view.length() > 0) || !view.isFinite()) {
            throw new IllegalArgumentException("camera eye and look-at point must differ and be finite");
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

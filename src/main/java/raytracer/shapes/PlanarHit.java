package raytracer.shapes;

import raytracer.core.ShadeRec;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/** Ray/plane arithmetic shared by the flat shapes (Plane, Rectangle, Disk): distance and projected hit point. */
final class PlanarHit {
    private PlanarHit() {
    }

    /** t where the ray meets the plane through (px, py, pz) with unit normal n; +infinity if parallel. */
    static double distance(Ray ray, double px, double py, double pz, double nx, double ny, double nz) {
        double denominator = ray.dx * nx + ray.dy * ny + ray.dz * nz;
        if (denominator == 0) {
            return Double.POSITIVE_INFINITY;
        }
        double t = ((px - ray.ox) * nx + (py - ray.oy) * ny + (pz - ray.oz) * nz) / denominator;
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }

    /**
     * Completes a hit on the plane: the point o + t d projected onto the plane (so only the
     * projection's rounding is left along the normal), its error bound and the normals.
     */
    static void complete(Ray ray, ShadeRec sr, double px, double py, double pz, double nx, double ny, double nz) {
        double hx = ray.atX(sr.t);
        double hy = ray.atY(sr.t);
        double hz = ray.atZ(sr.t);
        double off = (hx - px) * nx + (hy - py) * ny + (hz - pz) * nz;
        hx -= off * nx;
        hy -= off * ny;
        hz -= off * nz;
        sr.hitPoint.set(hx, hy, hz);
        double g = Rounding.gamma(8);
        double scale = Math.abs(px) + Math.abs(py) + Math.abs(pz) + Math.abs(hx) + Math.abs(hy) + Math.abs(hz);
        sr.hitError.set(g * scale, g * scale, g * scale);
        sr.normal.set(nx, ny, nz);
        sr.geometricNormal.set(nx, ny, nz);
    }
}

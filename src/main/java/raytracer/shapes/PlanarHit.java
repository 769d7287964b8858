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
     * t where the ray crosses the plane if that crossing is certainly in (0, tMax), else +infinity:
     * both ends must lie beyond t's error bound. With w = p - o, N = n . w and D = n . d as
     * computed, N is off by at most gamma(5) sum |w_i n_i| (one subtraction, then a dot product) and
     * D by gamma(3) sum |d_i n_i|; the ray's own errors move them by originError |n|_1 and
     * |t| directionError |n|_1. So t = N / D is off by the sum of those over |D| - gamma(3)
     * sum |d_i n_i|, plus its own rounding. For shadow rays: a plane through the light's point (a
     * ceiling around its lamp, a wall behind a point light) touches the ray's end and does not
     * block it, and one through the shaded point does not block its start.
     */
    static double crossesWithin(Ray ray, double tMax, double px, double py, double pz, double nx, double ny, double nz) {
        double wx = px - ray.ox;
        double wy = py - ray.oy;
        double wz = pz - ray.oz;
        double denominator = ray.dx * nx + ray.dy * ny + ray.dz * nz;
        double t = (wx * nx + wy * ny + wz * nz) / denominator;
        if (!(t > 0 & tMax - t > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double n1 = Math.abs(nx) + Math.abs(ny) + Math.abs(nz);
        double sumD = Math.abs(ray.dx * nx) + Math.abs(ray.dy * ny) + Math.abs(ray.dz * nz);
        double sumN = Math.abs(wx * nx) + Math.abs(wy * ny) + Math.abs(wz * nz);
        double certain = Math.abs(denominator) - Rounding.gamma(3) * sumD;
        double margin = (Rounding.gamma(5) * sumN + ray.originError * n1 + t * (Rounding.gamma(3) * sumD + ray.directionError * n1))
                        / certain + Rounding.gamma(1) * t;
        return certain > 0 && t - margin > 0 && tMax - t - margin > 0 ? t : Double.POSITIVE_INFINITY;
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

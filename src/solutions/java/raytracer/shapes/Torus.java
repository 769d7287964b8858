package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/**
 * Reference solution of exercise 5 (docs/teaching.md): a torus around the y axis, centred at the
 * origin, with swept radius a (axis to the centre of the tube) and tube radius b (Suffern,
 * chapter 19). Its points satisfy (|p|^2 + a^2 - b^2)^2 = 4 a^2 (x^2 + z^2); along a ray that is a quartic
 * in t, whose smallest root {@link QuarticRoot} finds. Move and turn it with an instance.
 */
public final class Torus extends GeometricObject {
    private final double a;
    private final double b;
    /**
     * How far from the surface the quartic can no longer tell the sides apart: its value is
     * computed with an error of a few ulps of (|p|^2 + a^2)^2 <= 4 (a + b)^4, and grows away from
     * the surface at |grad| = 8 a rho b >= 8 a (a - b) b. Secondary rays start at least this far off.
     */
    private final double sideError;

    public Torus(double a, double b) {
        if (!(b > 0) || !(a > b) || !Double.isFinite(a)) {
            throw new IllegalArgumentException("a torus needs a finite swept radius a greater than its tube radius b > 0, got a = "
                                               + a + ", b = " + b);
        }
        this.a = a;
        this.b = b;
        this.sideError = Rounding.gamma(32) * Math.pow(a + b, 4) / (a * b * (a - b));
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return recordIfCloser(firstHit(ray, sr.t), sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return firstHit(ray, tMax) < tMax;
    }

    /** The smallest t in (0, tMax) where the ray meets the torus, or +infinity. */
    private double firstHit(Ray ray, double tMax) {
        double dd = ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz;
        double od = ray.ox * ray.dx + ray.oy * ray.dy + ray.oz * ray.dz;
        // the bounding sphere of radius a + b, by the perpendicular distance of the ray from the centre
        double tc = -od / dd;
        double px = ray.ox + tc * ray.dx;
        double py = ray.oy + tc * ray.dy;
        double pz = ray.oz + tc * ray.dz;
        double r = a + b;
        double disc = (r * r - (px * px + py * py + pz * pz)) / dd;
        if (!(disc > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double half = Math.sqrt(disc);
        double lo = Math.max(0, tc - half);
        double hi = Math.min(tMax, tc + half);
        if (!(lo < hi)) {
            return Double.POSITIVE_INFINITY;
        }
        // the quartic in s = t - lo, from a point beside the torus, so that its coefficients keep their digits
        double ox = ray.ox + lo * ray.dx;
        double oy = ray.oy + lo * ray.dy;
        double oz = ray.oz + lo * ray.dz;
        double f = ox * ray.dx + oy * ray.dy + oz * ray.dz;
        double e = ox * ox + oy * oy + oz * oz + a * a - b * b;
        double a4 = 4 * a * a;
        double c4 = dd * dd;
        double c3 = 4 * dd * f;
        double c2 = 2 * dd * e + 4 * f * f - a4 * (ray.dx * ray.dx + ray.dz * ray.dz);
        double c1 = 4 * f * e - 2 * a4 * (ox * ray.dx + oz * ray.dz);
        double c0 = e * e - a4 * (ox * ox + oz * oz);
        double s = QuarticRoot.smallest(c4, c3, c2, c1, c0, 0, hi - lo, lo > 0);
        double t = lo + s;
        return t > 0 && t < tMax ? t : Double.POSITIVE_INFINITY;
    }

    /**
     * Completes the hit by projecting o + t d onto the surface: from the nearest point c of the tube's
     * centre circle, out to distance b. The projection is exact to a few ulps whatever the error of
     * t, and (p - c) / b is the outward unit normal.
     */
    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double x = ray.ox + sr.t * ray.dx;
        double y = ray.oy + sr.t * ray.dy;
        double z = ray.oz + sr.t * ray.dz;
        double rho = Math.hypot(x, z);
        double cx = a * x / rho;
        double cz = a * z / rho;
        double nx = x - cx;
        double nz = z - cz;
        double len = Math.sqrt(nx * nx + y * y + nz * nz);
        nx /= len;
        double ny = y / len;
        nz /= len;
        sr.hitPoint.set(cx + b * nx, b * ny, cz + b * nz);
        sr.normal.set(nx, ny, nz);
        sr.geometricNormal.set(nx, ny, nz);
        double g = Rounding.gamma(8);
        sr.hitError.set(sideError + g * (Math.abs(sr.hitPoint.x) + a + b), sideError + g * b,
                        sideError + g * (Math.abs(sr.hitPoint.z) + a + b));
        // u around the axis, v around the tube, both in [0, 1)
        sr.u = (Math.atan2(-z, x) / (2 * Math.PI) + 1) % 1;
        sr.v = (Math.atan2(ny, nx * x / rho + nz * z / rho) / (2 * Math.PI) + 1) % 1;
    }

    @Override
    public BBox boundingBox() {
        double r = a + b;
        return new BBox(-r, -b, -r, r, b, r);
    }
}

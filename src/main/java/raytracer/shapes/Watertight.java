package raytracer.shapes;

import raytracer.core.ShadeRec;
import raytracer.math.Rounding;
import raytracer.math.ShearedRay;
import raytracer.math.Vector3D;

/**
 * Watertight ray/triangle intersection (Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2013). The vertices are moved into a frame where the ray runs along +z from
 * the origin; the three 2D edge functions are then computed from the same operands for both
 * triangles that share an edge, so a ray through an edge or vertex hits at least one of them.
 * Shared by the single {@link Triangle} and the mesh triangles.
 */
public final class Watertight {
    private Watertight() {
    }

    /**
     * Distance to the triangle (vertices at offsets {@code a}, {@code b}, {@code c} of the flat
     * xyz array {@code v}) if it lies in (0, tMax), with the barycentrics of b and c written to
     * {@code sr.b1}, {@code sr.b2}; otherwise +infinity and {@code sr} untouched. An edge-on or
     * degenerate triangle (det = 0) gets an infinite or NaN t, which fails the range test.
     */
    public static double intersect(ShearedRay ray, double[] v, int a, int b, int c, double tMax, ShadeRec sr) {
        // JIT notes (README, "Speed"): no branch here may be rarely taken, since the JIT compiles
        // such a branch as a trap and taking it discards the compiled code; and the method stays
        // above the inlining limit, since inlined into the traversal it traced no faster and took
        // four times as long to compile, during the first render.
        int kx = ray.kx();
        int ky = ray.ky();
        int kz = ray.kz();
        double ox = ray.originX();
        double oy = ray.originY();
        double oz = ray.originZ();
        double sx = ray.sx();
        double sy = ray.sy();
        // vertices relative to the ray origin in the (kx, ky, kz) axis order, sheared so that the
        // ray direction becomes (0, 0, 1)
        double az = v[a + kz] - oz;
        double bz = v[b + kz] - oz;
        double cz = v[c + kz] - oz;
        double ax = v[a + kx] - ox - sx * az;
        double ay = v[a + ky] - oy - sy * az;
        double bx = v[b + kx] - ox - sx * bz;
        double by = v[b + ky] - oy - sy * bz;
        double cx = v[c + kx] - ox - sx * cz;
        double cy = v[c + ky] - oy - sy * cz;
        // scaled barycentrics: 2D edge functions
        double u = cx * by - cy * bx;
        double w1 = ax * cy - ay * cx;
        double w2 = bx * ay - by * ax;
        // outside when the edge functions have both signs (a zero counts as either); plain
        // comparisons joined without short-circuits, since Math.min and Math.max on doubles cost a
        // blend sequence each for NaN and -0.0 rules that this test does not need
        boolean someNegative = u < 0 | w1 < 0 | w2 < 0;
        boolean somePositive = u > 0 | w1 > 0 | w2 > 0;
        if (someNegative & somePositive) {
            return Double.POSITIVE_INFINITY;
        }
        double sz = ray.sz();
        double det = u + w1 + w2;
        double t = (u * (sz * az) + w1 * (sz * bz) + w2 * (sz * cz)) / det;
        // 0 < t < tMax as one test (a NaN fails it): with gradual underflow tMax - t > 0 exactly when t < tMax
        if (!(t > 0 & tMax - t > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        sr.b1 = w1 / det;
        sr.b2 = w2 / det;
        return t;
    }

    /**
     * Writes the hit point b0 a + b1 b + b2 c and its error bound gamma(7) sum |b_i p_i|
     * (pbrt-v3, section 3.9.4) into {@code sr}.
     */
    public static void interpolate(double[] v, int a, int b, int c, double b0, double b1, double b2,
                                   ShadeRec sr) {
        double g = Rounding.gamma(7);
        double x0 = b0 * v[a];
        double x1 = b1 * v[b];
        double x2 = b2 * v[c];
        double y0 = b0 * v[a + 1];
        double y1 = b1 * v[b + 1];
        double y2 = b2 * v[c + 1];
        double z0 = b0 * v[a + 2];
        double z1 = b1 * v[b + 2];
        double z2 = b2 * v[c + 2];
        sr.hitPoint.set(x0 + x1 + x2, y0 + y1 + y2, z0 + z1 + z2);
        sr.hitError.set(g * (Math.abs(x0) + Math.abs(x1) + Math.abs(x2)),
                        g * (Math.abs(y0) + Math.abs(y1) + Math.abs(y2)),
                        g * (Math.abs(z0) + Math.abs(z1) + Math.abs(z2)));
    }

    /**
     * True when the edges e1, e2 are (nearly) parallel: |e1 x e2| is within rounding of zero relative
     * to |e1| |e2|. Such a triangle has no area and never reports a hit.
     */
    public static boolean isDegenerate(Vector3D e1, Vector3D e2, Vector3D cross) {
        double area = cross.length();
        return !(area > Rounding.gamma(4) * e1.length() * e2.length()) || !Double.isFinite(area);
    }
}

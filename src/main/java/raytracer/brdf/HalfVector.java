package raytracer.brdf;

import raytracer.math.MutableVec3;

/** The half vector's cosine with the normal, cos(theta_h), shared by the microfacet-style lobes. */
final class HalfVector {
    private HalfVector() {
    }

    /** cos(theta_h) for H = normalize(wi + wo), or -1 when wi = -wo (no half vector). */
    static double cosThetaH(MutableVec3 n, MutableVec3 wi, MutableVec3 wo) {
        double hx = wi.x + wo.x;
        double hy = wi.y + wo.y;
        double hz = wi.z + wo.z;
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (!(len > 0)) {
            return -1;
        }
        return Math.min(1, (n.x * hx + n.y * hy + n.z * hz) / len);
    }
}

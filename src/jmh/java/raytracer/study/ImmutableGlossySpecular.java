package raytracer.study;

import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * Phong's lobe, f = scale cs cos^e(alpha) with alpha between wo and the mirror direction of wi
 * (report eq. 1, Suffern section 15.3), in values: scale is ks, or ks (e + 2) / (2 pi) normalised.
 */
record ImmutableGlossySpecular(RGBColor cs, double scale, double exp) {

    RGBColor f(Hit hit, Vector3D wi) {
        Vector3D n = hit.normal();
        Vector3D r = wi.negate().add(n.scale(2 * n.dot(wi)));
        double rDotWo = r.dot(hit.wo());
        return rDotWo > 0 ? cs.scale(scale * Math.pow(rDotWo, exp)) : RGBColor.BLACK;
    }
}

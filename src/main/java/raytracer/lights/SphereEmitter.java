package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Rounding;
import raytracer.math.MutableVec3;

/**
 * A sphere emitting outward. Seen from a point outside it, sampled uniformly over the cone of
 * directions it fills there, the cap of half-angle theta_max, sin(theta_max) = r / D at distance D
 * from its centre (pbrt-v4's Sphere::Sample with a reference point; pbrt-v3, section 14.2.2): every
 * sample reaches the visible cap. From a point inside it or on it (which it cannot light: its
 * surface faces away), and where the cone is too narrow for its density to be represented,
 * uniformly over its whole area (z = 1 - 2u, phi = 2 pi v).
 */
final class SphereEmitter implements Emitter {
    /**
     * Below this sin^2(theta_max) (a solid angle near 1e-271) the cone's density
     * 1 / (2 pi (1 - cos theta_max)) nears overflow; such a sphere is sampled by area.
     */
    private static final double MIN_SIN2_THETA_MAX = 0x1.0p-900;

    private final Point3D center;
    private final double radius;
    private final double inverseArea;

    SphereEmitter(Point3D center, double radius) {
        if (!(radius > 0)) {
            throw new IllegalArgumentException("a sphere light needs a positive radius, got " + radius);
        }
        this.center = center;
        this.radius = radius;
        this.inverseArea = 1 / area();
    }

    /**
     * By the sample's error bound along the normal: the unit vector from a square root, a sine and
     * a cosine, times the radius, plus the centre, is within gamma(16) of their sizes; plus two
     * ulps of that size, so that adding the move cannot round it away.
     */
    @Override
    public void moveOff(MutableVec3 point, MutableVec3 n) {
        double size = Math.max(Math.abs(center.x()), Math.max(Math.abs(center.y()), Math.abs(center.z()))) + radius;
        double move = Rounding.gamma(16) * size * (Math.abs(n.x) + Math.abs(n.y) + Math.abs(n.z)) + 0x1.0p-51 * size;
        point.set(point.x + move * n.x, point.y + move * n.y, point.z + move * n.z);
    }

    /**
     * The cone around w = (c - p) / D: cos(theta) = 1 - u (1 - cos theta_max), phi = 2 pi v, and the
     * direction's nearer point on the sphere, at angle alpha from -w seen from the centre (pbrt-v4,
     * Sphere::Sample: cos(alpha) = sin^2(theta) / s + cos(theta) sqrt(1 - sin^2(theta) / s^2),
     * s = sin(theta_max)). Written so that nothing cancels, for cones of any width:
     * 1 - cos(theta_max) = s^2 / (1 + cos theta_max), cos^2(theta_max) = (D - r)(D + r) / D^2,
     * s^2 - sin^2(theta) = om (1 - u)(2 - om (1 + u)) with om = 1 - cos(theta_max), and
     * sin(alpha) = sin(theta) (cos(theta) - sqrt(s^2 - sin^2 theta)) / s with the difference
     * rationalised to cos^2(theta_max) / (cos(theta) + sqrt(s^2 - sin^2 theta)). Its area density
     * is pdf_omega cos(theta_light) / d^2, pdf_omega = 1 / (2 pi om).
     */
    @Override
    public double sample(MutableVec3 p, double u, double v, MutableVec3 point, MutableVec3 n) {
        double wx = center.x() - p.x;
        double wy = center.y() - p.y;
        double wz = center.z() - p.z;
        double distance = Math.sqrt(wx * wx + wy * wy + wz * wz);
        double s = radius / distance;
        double sin2Max = s * s;
        if (!(distance > radius) || !(sin2Max >= MIN_SIN2_THETA_MAX)) {
            sampleArea(u, v, point, n);
            return inverseArea;
        }
        wx /= distance;
        wy /= distance;
        wz /= distance;
        double cos2Max = (distance - radius) * (distance + radius) / (distance * distance);
        double om = sin2Max / (1 + Math.sqrt(cos2Max));
        double x = u * om;
        double cosTheta = 1 - x;
        double sin2Theta = x * (2 - x);
        double rest = Math.sqrt(om * (1 - u) * (2 - om * (1 + u)));
        double sinAlpha = Math.sqrt(sin2Theta) * cos2Max / (s * (cosTheta + rest));
        double cosAlpha = (sin2Theta + cosTheta * rest) / s;
        double phi = 2 * Math.PI * v;
        double ca = Math.cos(phi) * sinAlpha;
        double sa = Math.sin(phi) * sinAlpha;
        // a frame (e1, e2, w) without branches (Duff et al., "Building an Orthonormal Basis,
        // Revisited", JCGT 6(1), 2017); the normal is -cos(alpha) w + sin(alpha) (cos phi e1 + sin phi e2)
        double sign = Math.copySign(1.0, wz);
        double k = -1 / (sign + wz);
        double m = wx * wy * k;
        double e1x = 1 + sign * wx * wx * k;
        double e1y = sign * m;
        double e1z = -sign * wx;
        double e2x = m;
        double e2y = sign + wy * wy * k;
        double e2z = -wy;
        n.set(ca * e1x + sa * e2x - cosAlpha * wx, ca * e1y + sa * e2y - cosAlpha * wy, ca * e1z + sa * e2z - cosAlpha * wz);
        point.set(center.x() + radius * n.x, center.y() + radius * n.y, center.z() + radius * n.z);
        double g = Emitter.geometricFactor(p, point, n);
        // a point at the cap's rim that faces away only by rounding has G = 0 and weighs nothing
        return g > 0 ? g / (2 * Math.PI * om) : inverseArea;
    }

    /** Uniform over the whole sphere: z = 1 - 2u, phi = 2 pi v. */
    private void sampleArea(double u, double v, MutableVec3 point, MutableVec3 n) {
        double z = 1 - 2 * u;
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * v;
        n.set(r * Math.cos(phi), r * Math.sin(phi), z);
        point.set(center.x() + radius * n.x, center.y() + radius * n.y, center.z() + radius * n.z);
    }

    @Override
    public double pdf(double px, double py, double pz, double distance, double cosLight) {
        double wx = center.x() - px;
        double wy = center.y() - py;
        double wz = center.z() - pz;
        double d = Math.sqrt(wx * wx + wy * wy + wz * wz);
        double s = radius / d;
        double sin2Max = s * s;
        if (!(d > radius) || !(sin2Max >= MIN_SIN2_THETA_MAX)) {
            return inverseArea;
        }
        double cos2Max = (d - radius) * (d + radius) / (d * d);
        double om = sin2Max / (1 + Math.sqrt(cos2Max));
        return cosLight / (distance * distance * 2 * Math.PI * om);
    }

    @Override
    public boolean mayLight(MutableVec3 p, MutableVec3 n) {
        return n.x * (center.x() - p.x) + n.y * (center.y() - p.y) + n.z * (center.z() - p.z) + radius > 0;
    }

    @Override
    public BBox bounds() {
        return new BBox(center.x() - radius, center.y() - radius, center.z() - radius,
                        center.x() + radius, center.y() + radius, center.z() + radius);
    }

    @Override
    public double area() {
        return 4 * Math.PI * radius * radius;
    }
}

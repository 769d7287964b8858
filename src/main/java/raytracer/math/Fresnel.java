package raytracer.math;

/**
 * Fresnel reflectance of a smooth boundary (Hecht, Optics, section 4.6; pbrt-v3 eq. 8.2-8.4):
 * the fraction of light reflected, the rest being refracted, as a function of the cosine of the
 * angle of incidence and the refractive indices on either side.
 */
public final class Fresnel {
    private Fresnel() {
    }

    /**
     * Unpolarised reflectance for light arriving from the side with index {@code etaI} onto a
     * boundary with index {@code etaT}; {@code cosI} is the cosine of the angle of incidence (in
     * [0, 1]). Returns 1 past the critical angle (total internal reflection).
     */
    public static double dielectric(double cosI, double etaI, double etaT) {
        return 0.5 * (parallel(cosI, etaI, etaT) + perpendicular(cosI, etaI, etaT));
    }

    /** Reflectance of light polarised in the plane of incidence (p): zero at Brewster's angle. */
    public static double parallel(double cosI, double etaI, double etaT) {
        double cosT = cosTransmitted(cosI, etaI, etaT);
        if (Double.isNaN(cosT)) {
            return 1;
        }
        double r = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
        return r * r;
    }

    /** Reflectance of light polarised perpendicular to the plane of incidence (s). */
    public static double perpendicular(double cosI, double etaI, double etaT) {
        double cosT = cosTransmitted(cosI, etaI, etaT);
        if (Double.isNaN(cosT)) {
            return 1;
        }
        double r = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
        return r * r;
    }

    /**
     * The cosine of the refraction angle by Snell's law, sin t = (etaI / etaT) sin i, or NaN when
     * sin t would exceed 1 (total internal reflection).
     */
    public static double cosTransmitted(double cosI, double etaI, double etaT) {
        double c = Math.min(1, Math.abs(cosI));
        double sinT2 = (etaI / etaT) * (etaI / etaT) * Math.max(0, 1 - c * c);
        return sinT2 >= 1 ? Double.NaN : Math.sqrt(1 - sinT2);
    }

    /**
     * Schlick's approximation (Schlick 1994) from the reflectance at normal incidence f0:
     * f0 + (1 - f0) (1 - cos)^5. The report's mirror uses it with f0 = 0.5.
     */
    public static double schlick(double f0, double cosI) {
        double m = 1 - Math.max(0, Math.min(1, cosI));
        double m2 = m * m;
        return f0 + (1 - f0) * m2 * m2 * m;
    }
}

package raytracer.reference;

/**
 * An area light of uniform radiance L whose irradiance at a point has a closed form:
 * E = L x (the projected solid angle it subtends, the integral of cos(theta) over it).
 */
public interface ExactLight {

    /**
     * The projected solid angle of the light's emitting side seen from point p with unit normal n:
     * the integral over the light of cos(theta) cos(theta') / r^2 dA; 0 where p is behind it.
     */
    double projectedSolidAngle(double px, double py, double pz, double nx, double ny, double nz);

    /** True when every point of the light is strictly on the side of the plane (p, n) that n points to. */
    boolean above(double px, double py, double pz, double nx, double ny, double nz);
}

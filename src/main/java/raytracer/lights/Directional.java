package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/** Light from one direction with no falloff, L = ls c (Suffern, section 14.4.1); the sun. */
public final class Directional extends Light {
    private final Vector3D towardLight;
    private final RGBColor radiance;

    /** {@code towardLight} points from the scene to the light. */
    public Directional(double ls, RGBColor color, Vector3D towardLight) {
        if (!(towardLight.length() > 0) || !towardLight.isFinite()) {
            throw new IllegalArgumentException("a directional light needs a finite, non-zero direction");
        }
        this.towardLight = towardLight.normalize();
        this.radiance = color.scale(ls);
    }

    @Override
    public double getDirection(ShadeRec sr, MutableVec3 wi) {
        wi.set(towardLight.x(), towardLight.y(), towardLight.z());
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public void L(ShadeRec sr, MutableRgb out) {
        out.set(radiance);
    }

    /** The unit direction from the scene to the light. */
    public Vector3D towardLight() {
        return towardLight;
    }

    /** L = ls c. */
    public RGBColor radiance() {
        return radiance;
    }
}

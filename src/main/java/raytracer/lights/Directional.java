package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.HalfSpace;
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
    public boolean isBlack() {
        return radiance.isBlack();
    }

    /** A shadow ray runs to infinity along the light's direction: it stays in h if that direction does not lead out. */
    @Override
    public boolean keepsShadowRaysWithin(HalfSpace h) {
        return h.nx() * towardLight.x() + h.ny() * towardLight.y() + h.nz() * towardLight.z() <= 0;
    }

    /**
     * A shadow ray from a point of h along the light's direction crosses h's plane at a finite
     * distance when the direction leads out by more than the margin: at most |n . q - d| / (n . l),
     * and the scene's extent (below 1e150) over 2^-30 stays far below the largest double.
     */
    @Override
    public boolean liesBeyond(HalfSpace h) {
        double out = h.nx() * towardLight.x() + h.ny() * towardLight.y() + h.nz() * towardLight.z();
        return out > HalfSpace.MARGIN * (Math.abs(h.nx()) + Math.abs(h.ny()) + Math.abs(h.nz()));
    }

    @Override
    public String description() {
        return "directional light";
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

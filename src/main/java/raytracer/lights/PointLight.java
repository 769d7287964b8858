package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * A point light of intensity I = ls c: it gives irradiance I cos(theta) / r^2 (the inverse-square
 * law; Suffern's point light of section 14.4 has no falloff, a departure listed in
 * docs/teaching.md), so {@link #L} returns I / r^2 and the material multiplies by cos(theta).
 */
public final class PointLight extends Light {
    private final double px;
    private final double py;
    private final double pz;
    private final RGBColor intensity;

    public PointLight(double ls, RGBColor color, Point3D position) {
        this.px = position.x();
        this.py = position.y();
        this.pz = position.z();
        this.intensity = color.scale(ls);
    }

    @Override
    public double getDirection(ShadeRec sr, MutableVec3 wi) {
        wi.set(px - sr.hitPoint.x, py - sr.hitPoint.y, pz - sr.hitPoint.z);
        double distance = wi.length();
        wi.set(wi.x / distance, wi.y / distance, wi.z / distance);
        return distance;
    }

    /** The shadow ray ends at the light's position itself, exact as given. */
    @Override
    public boolean inShadow(ShadeRec sr, double distance) {
        return sr.world.shadowHit(sr.spawnRayTo(px, py, pz, sr.scratch.shadowRay), 1, sr);
    }

    @Override
    public boolean isBlack() {
        return intensity.isBlack();
    }

    @Override
    public boolean keepsShadowRaysWithin(HalfSpace h) {
        return h.contains(px, py, pz);
    }

    /**
     * Only for a plane perpendicular to an axis: a hit on a tilted plane far from the light is off
     * the plane by rounding that grows with its distance, and may come out on the light's side,
     * where one on an axis-aligned plane is projected onto the plane's coordinate (PlanarHit).
     */
    @Override
    public boolean liesBeyond(HalfSpace h) {
        return h.isAxisAligned() && h.excludes(new BBox(px, py, pz, px, py, pz));
    }

    @Override
    public String description() {
        return "point light";
    }

    @Override
    public void L(ShadeRec sr, MutableRgb out) {
        double dx = px - sr.hitPoint.x;
        double dy = py - sr.hitPoint.y;
        double dz = pz - sr.hitPoint.z;
        out.set(intensity).scale(1 / (dx * dx + dy * dy + dz * dz));
    }

    public Point3D position() {
        return new Point3D(px, py, pz);
    }

    /** I = ls c. */
    public RGBColor intensity() {
        return intensity;
    }
}

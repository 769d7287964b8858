package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/** A light source (Suffern, chapter 14). */
public abstract class Light {
    private boolean castsShadows = true;

    /**
     * Writes the unit direction from the hit towards the light into {@code wi} and returns the
     * distance to the light (infinite for a directional light).
     */
    public abstract double getDirection(ShadeRec sr, Vec3 wi);

    /** Writes the incident radiance (or, for point lights, the irradiance factor I / r^2) into {@code out}. */
    public abstract void L(ShadeRec sr, Rgb out);

    /** True when something casts a shadow on the hit along {@code shadowRay} before the light. */
    public boolean inShadow(Ray shadowRay, double distance, ShadeRec sr) {
        return sr.world.shadowHit(shadowRay, distance, sr);
    }

    public boolean castsShadows() {
        return castsShadows;
    }

    public void setCastsShadows(boolean castsShadows) {
        this.castsShadows = castsShadows;
    }
}

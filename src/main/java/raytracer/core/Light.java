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

    /**
     * False when the light cannot reach the hit at all (behind it, or below its tangent plane), so
     * that shading skips it without drawing samples; lights without extent say true.
     */
    public boolean mayIlluminate(ShadeRec sr) {
        return true;
    }

    /** True for lights with a surface to sample (area lights); false for points and directions. */
    public boolean hasExtent() {
        return false;
    }

    /**
     * How many samples this light takes per shaded point: 1 for point and directional lights, the
     * configured number for area lights (Suffern, chapter 18).
     */
    public int sampleCount() {
        return 1;
    }

    /**
     * Picks the point of the light for the sample ({@code u}, {@code v}) in [0,1)^2 and writes the
     * unit direction towards it into {@code wi}; returns the distance. Lights without extent ignore
     * the sample.
     */
    public double sample(ShadeRec sr, double u, double v, Vec3 wi) {
        return getDirection(sr, wi);
    }

    /**
     * The Monte Carlo weight of the last sample: the geometry term over the sample's density,
     * cos(theta_light) / d^2 / pdf_area for an area light; 1 for lights without extent.
     */
    public double geometryOverPdf(ShadeRec sr) {
        return 1;
    }

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

package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/** A light source (Suffern, chapter 14). */
public abstract class Light {
    private boolean castsShadows = true;

    /**
     * Writes the unit direction from the hit towards the light into {@code wi} and returns the
     * distance to the light (infinite for a directional light).
     */
    public abstract double getDirection(ShadeRec sr, MutableVec3 wi);

    /** Writes the incident radiance (or, for point lights, the irradiance factor I / r^2) into {@code out}. */
    public abstract void L(ShadeRec sr, MutableRgb out);

    /**
     * False when the light cannot reach the hit at all (behind it, or below its tangent plane), so
     * that shading skips it without drawing samples; lights without extent say true.
     */
    public boolean mayIlluminate(ShadeRec sr) {
        return true;
    }

    /**
     * True for lights with a surface to sample (area lights): only the AreaLighting tracer's
     * {@code areaLightShade} can take them, and traced rays may find their surfaces (when the
     * scene also shows them as emissive objects).
     */
    public boolean hasExtent() {
        return false;
    }

    /**
     * How many samples this light takes per shaded point at most: 1 for point and directional
     * lights, the configured number for area lights (Suffern, chapter 18). Their values come from
     * the worker's {@link PixelSamples}, stratified across the pixel's samples.
     */
    public int sampleCount() {
        return 1;
    }

    /**
     * Picks the point of the light for the sample ({@code u}, {@code v}) in [0,1)^2 and writes the
     * unit direction towards it into {@code wi}; returns the distance. Lights without extent ignore
     * the sample.
     */
    public double sample(ShadeRec sr, double u, double v, MutableVec3 wi) {
        return getDirection(sr, wi);
    }

    /**
     * The geometric factor of the last sample (Suffern, chapter 18): cos(theta_light) / d^2, which
     * turns the area measure of an area light into solid angle at the hit; 1 for lights without
     * extent, whose {@link #L} already is what reaches the hit.
     */
    public double G(ShadeRec sr) {
        return 1;
    }

    /**
     * The density of the last sample over the light's area (Suffern, chapter 18: 1 / area for
     * uniform sampling); 1 for lights without extent. The estimate of a light's contribution is
     * then the book's L f G cos(theta_i) / pdf.
     */
    public double pdf(ShadeRec sr) {
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

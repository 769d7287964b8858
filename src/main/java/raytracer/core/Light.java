package raytracer.core;

import java.util.List;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/** A light source (Suffern, chapter 14). */
public abstract class Light {
    private boolean castsShadows = true;
    private boolean shadowRaysLeftOut;
    private boolean surfaceShown;
    /** Its place in the scene's list of lights as added, kept when the analysis leaves others out. */
    private int number;

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
     * True when traced rays can find this light's surface: an area light whose emitting shape is
     * also an object of the scene ({@link #showSurface}). A material that samples both the light
     * and its own lobe then weighs the two (multiple importance sampling); otherwise only the
     * light's samples can see it.
     */
    public final boolean canBeHit() {
        return surfaceShown;
    }

    /** Records that the light's emitting surface was added to the scene as an object (a visible area light). */
    public final void showSurface() {
        if (!hasExtent()) {
            throw new IllegalStateException("a " + description() + " has no surface to show");
        }
        surfaceShown = true;
    }

    /**
     * The density, over solid angle at the point (fromX, fromY, fromZ), with which this light's
     * sampling from there picks the direction to a point of its surface {@code distance} away, seen
     * at {@code cosLight} from its normal: {@link #pdf} d^2 / cos(theta_light) (Suffern, chapter 18).
     * 0 for lights without extent, whose one direction no traced ray can find.
     */
    public double directionPdf(double fromX, double fromY, double fromZ, double distance, double cosLight) {
        return 0;
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
     * The density of the last sample over the light's area (Suffern, chapter 18: 1 / area for uniform
     * sampling; pdf_omega cos(theta_light) / d^2 for sampling by solid angle); 1 for lights without
     * extent. The estimate of a light's contribution is then the book's L f G cos(theta_i) / pdf.
     */
    public double pdf(ShadeRec sr) {
        return 1;
    }

    /**
     * Called by {@link World#prepare} with the bounding boxes of the scene's objects, the only
     * places its light can fall: a light with a choice of how to draw its samples makes it here,
     * once for the frame, the same at every point.
     */
    public void prepare(List<BBox> receivers) {
    }

    /**
     * True when something casts a shadow on {@code sr}'s hit from this light: a shadow-casting
     * object lies between the hit and the light's point in direction sr.wi, {@code distance} away
     * (+infinity for a light at infinity). The shadow ray runs from the hit, offset off its surface
     * ({@link ShadeRec#spawnRay}), to that point ({@link ShadeRec#spawnRayTo}); a surface through
     * either end touches the ray without blocking it. Lights that know their point exactly
     * override this to aim at it; here it is rebuilt from the direction and the distance, and the
     * ray's direction error grows by that rounding.
     */
    public boolean inShadow(ShadeRec sr, double distance) {
        MutableVec3 wi = sr.wi;
        Ray shadowRay = sr.scratch.shadowRay;
        if (distance == Double.POSITIVE_INFINITY) {
            return sr.world.shadowHit(sr.spawnRay(wi.x, wi.y, wi.z, shadowRay), Double.POSITIVE_INFINITY, sr);
        }
        MutableVec3 p = sr.hitPoint;
        sr.spawnRayTo(p.x + distance * wi.x, p.y + distance * wi.y, p.z + distance * wi.z, shadowRay);
        double reach = Math.max(Math.abs(p.x), Math.max(Math.abs(p.y), Math.abs(p.z))) + distance;
        shadowRay.setErrors(0, shadowRay.directionError + Rounding.gamma(4) * reach);
        return sr.world.shadowHit(shadowRay, 1, sr);
    }

    public boolean castsShadows() {
        return castsShadows;
    }

    /**
     * The book's test before a light sample counts, casts_shadows() and in_shadow(): true when the
     * light casts shadows and one falls on the hit ({@link #inShadow}). A shadow ray the scene
     * analysis left out ({@link #leaveOutShadowRays}) is counted where it would have been traced.
     */
    public final boolean shadowed(ShadeRec sr, double distance) {
        if (castsShadows) {
            return inShadow(sr, distance);
        }
        if (shadowRaysLeftOut) {
            sr.scratch.skipped[Skipped.SHADOW_RAYS]++;
        }
        return false;
    }

    public void setCastsShadows(boolean castsShadows) {
        this.castsShadows = castsShadows;
    }

    /**
     * Stops tracing shadow rays towards this light because the scene analysis proved that none
     * could be blocked; {@link #shadowed} counts the rays no longer traced
     * ({@link Skipped#SHADOW_RAYS}).
     */
    public void leaveOutShadowRays() {
        castsShadows = false;
        shadowRaysLeftOut = true;
    }

    /**
     * Its place in the world's list of lights when it was added ({@link World#addLight}): it numbers
     * the light's sample dimension, so that leaving another light out moves none of its samples.
     */
    public int number() {
        return number;
    }

    void setNumber(int number) {
        this.number = number;
    }

    /** True after {@link #leaveOutShadowRays}: a shadow ray was due, and is counted instead of traced. */
    public boolean shadowRaysLeftOut() {
        return shadowRaysLeftOut;
    }

    /** True when the light emits nothing at all ({@link #L} is black wherever it is asked). */
    public boolean isBlack() {
        return false;
    }

    /**
     * True when shading draws samples of this light from the pixel's sample dimensions (lights
     * with extent). Each value is a function of its pixel, index and dimension, so leaving work
     * out moves no other; but the dimension is numbered by the light's place in the list, so the
     * analysis keeps such a light (and, to stay on the safe side, the rays that shade with it).
     */
    public boolean drawsSamples() {
        return false;
    }

    /**
     * True when every shadow ray towards this light that starts inside {@code h} ends inside it:
     * every point of the light lies in {@code h} (for a directional light: its direction does not
     * lead out of {@code h}). Lights that cannot tell say false.
     */
    public boolean keepsShadowRaysWithin(HalfSpace h) {
        return false;
    }

    /**
     * True when the whole light lies strictly outside {@code h}, past its plane by
     * {@link HalfSpace#excludes}'s margin (relative to h's size, which the caller sets to the
     * scene's), so that a shadow ray towards it from a point of {@code h} crosses that plane
     * before it arrives, and a hit on the plane, its normal turned into {@code h}, finds the light
     * behind it (for a directional light: its direction leads out of {@code h} by more than that
     * margin). Lights that cannot tell say false.
     */
    public boolean liesBeyond(HalfSpace h) {
        return false;
    }

    /** What the light is, for messages ("point light"). */
    public String description() {
        return getClass().getSimpleName();
    }
}

package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.SampleMapping;
import raytracer.math.MutableVec3;

/**
 * Reference solution of exercise 4 (docs/teaching.md): ambient occlusion (Suffern, chapter 17).
 * The world's ambient light, L = ls c times the fraction of {@code samples} directions, drawn with
 * density cos(theta) / pi about the normal, along which a shadow ray meets nothing. The cosine
 * weighting makes the fraction an estimate of the irradiance that the open sky would bring.
 */
public final class AmbientOccluder extends Light {
    private final RGBColor radiance;
    private final int samples;

    public AmbientOccluder(double ls, RGBColor color, int samples) {
        if (samples < 1) {
            throw new IllegalArgumentException("ambient occlusion needs at least 1 sample, got " + samples);
        }
        this.radiance = color.scale(ls);
        this.samples = samples;
        // it casts shadows (the default), so the scene analysis keeps what could occlude it
    }

    /** Ambient light has no one direction. */
    @Override
    public double getDirection(ShadeRec sr, MutableVec3 wi) {
        wi.set(0, 0, 0);
        return 0;
    }

    @Override
    public void L(ShadeRec sr, MutableRgb out) {
        // sr.wi is free here: a material takes its ambient term before any light's direction
        MutableVec3 w = sr.wi;
        Ray shadowRay = sr.scratch.shadowRay;
        int open = 0;
        for (int i = 0; i < samples; i++) {
            SampleMapping.toHemisphere(sr.scratch.rng.nextDouble(), sr.scratch.rng.nextDouble(), 1,
                                       sr.normal.x, sr.normal.y, sr.normal.z, w);
            sr.spawnRay(w.x, w.y, w.z, shadowRay);
            if (!sr.world.shadowHit(shadowRay, Double.POSITIVE_INFINITY, sr)) {
                open++;
            }
        }
        out.set(radiance).scale((double) open / samples);
    }
}

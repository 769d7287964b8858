package raytracer.materials;

import java.util.ArrayList;
import java.util.List;
import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.core.Background;
import raytracer.core.Light;
import raytracer.core.Material;
import raytracer.core.PixelSamples;
import raytracer.core.Sampler;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Texture;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * Glossy Phong (report section 2.1, figure 1b; Suffern, chapter 25): the diffuse part is lit
 * directly, while the specular part traces {@code samples} rays around the mirror direction, drawn
 * by the lobe's sample_f, so that the whole scene is reflected blurred. Every light also gives the
 * specular term directly: point and directional lights, which no ray can hit, alone; an area light
 * through its samples, weighed against the glossy rays that find its visible surface by multiple
 * importance sampling ({@link GlossyLightMis}), so its highlight is there whether or not the light
 * is visible, the rays are traced or the pass shows reflection, and is counted once.
 */
public final class GlossyReflector extends Material {
    /** Whether a texture that reads u, v replaced the plain diffuse colour. */
    private boolean textured;
    /** Seen by rays reflected or refracted off this object that escape, instead of the scene's background. */
    private Background reflectionMap;
    private final double ka;
    private final double kd;
    private final GlossySpecular specular;
    private DirectLighting lighting;
    private final int samples;
    private final GlossyLightMis mis;

    public GlossyReflector(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, int samples,
                           boolean normalized) {
        if (samples < 1 || samples > Sampler.MAX_SAMPLES) {
            throw new IllegalArgumentException("glossy samples must be 1 to " + Sampler.MAX_SAMPLES + ", got " + samples);
        }
        this.ka = ka;
        this.kd = kd;
        this.specular = new GlossySpecular(ks, cs, exp, normalized);
        this.mis = new GlossyLightMis(specular, samples);
        this.lighting = new DirectLighting(new Lambertian(ka, cd), new Lambertian(kd, cd), specular, mis);
        this.samples = samples;
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        textured = texture.usesTextureCoordinates();
        this.lighting = new DirectLighting(new Lambertian(ka, texture), new Lambertian(kd, texture), specular, mis);
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        lighting.shade(sr, out);
        reflectGlossy(sr, out);
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        lighting.areaLightShade(sr, out);
        reflectGlossy(sr, out);
    }

    /**
     * Adds the average over the glossy rays of the radiance each brings back times its weight
     * f cos(theta_i) / pdf (Suffern, chapter 25). The directions come from the glossy dimension of
     * this hit's path, stratified across the pixel's samples, and each ray names its own path. A
     * ray that finds the surface of an area light this hit also samples brings back its radiance
     * weighed against those samples ({@link GlossyLightMis}). The rays see the environment the
     * pass gives reflected rays (magenta for the first hit of the magenta-reflection pass).
     */
    private void reflectGlossy(ShadeRec sr, MutableRgb out) {
        int next = sr.depth + 1;
        WorkerScratch scratch = sr.scratch;
        if (next > sr.world.viewPlane().maxDepth() || !scratch.policy.showsReflection(sr.depth)) {
            return;
        }
        int n = mis.glossyRays(sr);
        PixelSamples pattern = scratch.samples;
        MutableVec3 wi = sr.wi;
        MutableRgb weight = scratch.weight(sr.depth);
        MutableRgb incoming = scratch.color(next);
        double r = 0;
        double g = 0;
        double b = 0;
        for (int i = 0; i < n; i++) {
            pattern.get2D(sr.depth, PixelSamples.GLOSSY, i, n);
            if (!specular.sampleF(sr, sr.wo, pattern.u, pattern.v, wi, weight)) {
                continue; // below the surface: zero, but it counts in the average
            }
            if (!scratch.policy.recordBranchWeight(sr.depth, weight.r / n, weight.g / n, weight.b / n)) {
                continue;
            }
            Ray ray = sr.spawnRay(wi.x, wi.y, wi.z, scratch.ray(next));
            pattern.branch(sr.depth, PixelSamples.GLOSSY_RAY, i, n);
            scratch.secondaryRays++;
            scratch.setEnvironment(next, scratch.policy.reflectedEnvironment(sr.depth, reflectionMap));
            scratch.clearEmitter(next);
            sr.world.tracer().traceRay(ray, next, scratch, incoming);
            Light emitter = scratch.emitter(next);
            if (emitter != null) {
                incoming.scale(mis.glossyRayWeight(sr, wi, n, lighting.lightSamplesToward(sr, emitter, wi), scratch.emitterPdf(next)));
            }
            r += incoming.r * weight.r;
            g += incoming.g * weight.g;
            b += incoming.b * weight.b;
        }
        out.r += r / n;
        out.g += g / n;
        out.b += b / n;
    }

    /** True unless ks or the specular colour is 0. */
    @Override
    public boolean needsReflection() {
        return !specular.isBlack();
    }

    /** Glossy rays are traced even of weight 0 (the lobe's samples are drawn before their weights are known). */
    @Override
    public boolean tracesRays() {
        return true;
    }

    /** The directions of the glossy rays come from the pixel's sample dimensions (see {@link raytracer.core.Light#drawsSamples}). */
    @Override
    public boolean drawsSamples() {
        return true;
    }

    @Override
    public List<Skip> simplify(World world, boolean mayDropRays) {
        List<Skip> skips = new ArrayList<>();
        lighting = lighting.simplified(world, name(), skips);
        return skips;
    }

    /** Gives this object its own environment for its reflections (report section 1); null: the scene's. */
    public void setReflectionMap(Background reflectionMap) {
        this.reflectionMap = reflectionMap;
    }

    @Override
    public boolean usesTextureCoordinates() {
        return textured;
    }
}

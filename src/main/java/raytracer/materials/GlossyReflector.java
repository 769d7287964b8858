package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.core.Background;
import raytracer.core.Material;
import raytracer.core.Sampler;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.core.WorkerScratch;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/**
 * Glossy Phong (report section 2.1, figure 1b; Suffern, chapter 25): the diffuse part is lit
 * directly, while the specular part traces {@code samples} rays around the mirror direction,
 * distributed as cos^e, so that the whole scene, area lights included, is reflected blurred. Area
 * lights are therefore not sampled for the specular term; point and directional lights, which no
 * ray can hit, still give their highlight directly.
 */
public final class GlossyReflector extends Material {
    /** Seen by rays reflected or refracted off this object that escape, instead of the scene's background. */
    private Background reflectionMap;
    private Lambertian ambient;
    private Lambertian diffuse;
    private final double ka;
    private final double kd;
    private final GlossySpecular specular;
    private final int samples;

    public GlossyReflector(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp, int samples,
                           boolean normalized) {
        if (samples < 1) {
            throw new IllegalArgumentException("glossy samples must be at least 1, got " + samples);
        }
        this.ka = ka;
        this.kd = kd;
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
        this.specular = new GlossySpecular(ks, cs, exp, normalized);
        this.samples = samples;
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        this.ambient = new Lambertian(ka, texture);
        this.diffuse = new Lambertian(kd, texture);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, specular, false, false, out);
        int next = sr.depth + 1;
        if (next > sr.world.viewPlane().maxDepth() || !sr.world.pass().reflection(sr.depth)) {
            return;
        }
        WorkerScratch scratch = sr.scratch;
        Sampler sampler = sr.world.viewPlane().sampler();
        int n = sampler.supportedCount(samples);
        double[] xs = scratch.patternX(sr.depth, n);
        double[] ys = scratch.patternY(sr.depth);
        sampler.generate(n, scratch.rng, xs, ys);
        Vec3 wi = sr.wi;
        RGBColor cs = specular.color();
        Rgb incoming = scratch.color(next);
        double r = 0;
        double g = 0;
        double b = 0;
        for (int i = 0; i < n; i++) {
            double weight = specular.sample(sr, sr.wo, xs[i], ys[i], wi);
            if (weight <= 0) {
                continue; // below the surface: zero, but it counts in the average
            }
            if (!scratch.branch(sr.depth, weight * cs.r() / n, weight * cs.g() / n, weight * cs.b() / n)) {
                continue;
            }
            Ray ray = sr.spawnRay(wi.x, wi.y, wi.z, scratch.ray(next));
            scratch.secondaryRays++;
            scratch.setEnvironment(next, reflectionMap);
            sr.world.tracer().traceRay(ray, next, scratch, incoming);
            r += incoming.r * weight;
            g += incoming.g * weight;
            b += incoming.b * weight;
        }
        out.r += r * cs.r() / n;
        out.g += g * cs.g() / n;
        out.b += b * cs.b() / n;
    }

    /** Gives this object its own environment for its reflections (report section 1); null: the scene's. */
    public void setReflectionMap(Background reflectionMap) {
        this.reflectionMap = reflectionMap;
    }

    @Override
    public boolean tracesSecondaryRays() {
        return true;
    }
}

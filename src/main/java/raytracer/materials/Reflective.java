package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.brdf.PerfectSpecular;
import raytracer.core.Background;
import raytracer.core.Material;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.core.WorkerScratch;
import raytracer.math.Fresnel;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/**
 * Phong shading plus a perfect mirror term (Suffern, section 24.3; area lights: chapter 18): the
 * radiance traced along the mirror direction, scaled by the mirror's weight kr cr, is added to the
 * direct light. With {@code schlick} the reflected fraction grows towards grazing angles by
 * Schlick's Fresnel approximation with kr as the reflectance at normal incidence (report section
 * 3: the brown mirror sphere with 0.5); the mirror's weight is then cr alone.
 */
public final class Reflective extends Material {
    /** Whether a texture that reads u, v replaced the plain diffuse colour. */
    private boolean textured;
    /** Seen by rays reflected or refracted off this object that escape, instead of the scene's background. */
    private Background reflectionMap;
    private final double ka;
    private final double kd;
    private final GlossySpecular specular;
    private DirectLighting lighting;
    private final PerfectSpecular mirror;
    private final double kr;
    private final boolean schlick;

    public Reflective(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp,
                      double kr, RGBColor cr, boolean schlick) {
        this.kr = kr;
        this.schlick = schlick;
        this.ka = ka;
        this.kd = kd;
        this.specular = new GlossySpecular(ks, cs, exp, false);
        this.lighting = new DirectLighting(new Lambertian(ka, cd), new Lambertian(kd, cd), specular);
        this.mirror = new PerfectSpecular(schlick ? 1 : kr, cr);
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        textured = texture.usesTextureCoordinates();
        this.lighting = new DirectLighting(new Lambertian(ka, texture), new Lambertian(kd, texture), specular);
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        lighting.shade(sr, out);
        reflect(sr, out);
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        lighting.areaLightShade(sr, out);
        reflect(sr, out);
    }

    /** Adds the radiance along the mirror direction, times the mirror's weight and the Fresnel fraction. */
    private void reflect(ShadeRec sr, MutableRgb out) {
        int next = sr.depth + 1;
        WorkerScratch scratch = sr.scratch;
        RayTreePolicy policy = scratch.policy;
        if (next > sr.world.viewPlane().maxDepth() || !policy.showsReflection(sr.depth)) {
            return;
        }
        MutableRgb weight = scratch.weight(sr.depth);
        mirror.sampleF(sr, sr.wo, 0, 0, sr.wi, weight);
        double fraction = schlick && policy.angleDependent() ? Fresnel.schlick(kr, sr.normal.dot(sr.wo)) : schlick ? kr : 1;
        if (!policy.recordBranchWeight(sr.depth, weight.r * fraction, weight.g * fraction, weight.b * fraction)) {
            return;
        }
        Ray reflected = sr.spawnRay(sr.wi.x, sr.wi.y, sr.wi.z, scratch.ray(next));
        scratch.samples.branch(sr.depth, PixelSamples.REFLECTED, 0, 1);
        scratch.secondaryRays++;
        scratch.setEnvironment(next, policy.reflectedEnvironment(sr.depth, reflectionMap));
        MutableRgb incoming = scratch.color(next);
        sr.world.tracer().traceRay(reflected, next, scratch, incoming);
        out.addProduct(incoming, weight, fraction);
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

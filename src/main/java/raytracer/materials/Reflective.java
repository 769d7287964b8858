package raytracer.materials;

import java.util.ArrayList;
import java.util.List;
import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.brdf.PerfectSpecular;
import raytracer.core.Background;
import raytracer.core.Material;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.Texture;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
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
    private RGBColor cd;
    private final GlossySpecular specular;
    private DirectLighting lighting;
    private final PerfectSpecular mirror;
    private final double kr;
    private final boolean schlick;
    /** Set by {@link #simplify} when the mirror's weight kr cr is 0: its rays are counted, not traced. */
    private boolean mirrorLeftOut;
    /** The max depth when the mirror was left out (the analysis may cut it after): the rays counted are those it allowed. */
    private int leftOutBelow;

    public Reflective(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp,
                      double kr, RGBColor cr, boolean schlick) {
        this.kr = kr;
        this.schlick = schlick;
        this.ka = ka;
        this.kd = kd;
        this.cd = cd;
        this.specular = new GlossySpecular(ks, cs, exp, false);
        this.lighting = new DirectLighting(new Lambertian(ka, cd), new Lambertian(kd, cd), specular);
        this.mirror = new PerfectSpecular(schlick ? 1 : kr, cr);
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        textured = texture.usesTextureCoordinates();
        this.cd = null;
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
        if (mirrorLeftOut) {
            // counted where the ray would have been traced: within the depth, and of weight 0 only with no cutoff
            if (next <= leftOutBelow && policy.showsReflection(sr.depth) && policy.recordBranchWeight(sr.depth, 0, 0, 0)) {
                scratch.skipped[Skipped.SECONDARY_RAYS]++;
            }
            return;
        }
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

    /** True unless the mirror's weight kr cr is 0 (with Schlick's Fresnel: unless cr is black). */
    @Override
    public boolean needsReflection() {
        return !mirror.isBlack();
    }

    @Override
    public boolean tracesRays() {
        return !mirrorLeftOut;
    }

    @Override
    public List<Skip> simplify(World world, boolean mayDropRays) {
        List<Skip> skips = new ArrayList<>();
        lighting = lighting.simplified(world, name(), skips);
        if (mirror.isBlack() && mayDropRays && !mirrorLeftOut) {
            mirrorLeftOut = true;
            leftOutBelow = world.viewPlane().maxDepth();
            skips.add(new Skip(Skipped.SECONDARY_RAYS, "mirror rays of weight 0 not traced", "material '" + name()
                               + "': kr or its colour is 0, and no light or material of the scene draws random numbers"));
        }
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

    /** The object's own environment for its reflections, or null for the scene's. */
    public Background reflectionMap() {
        return reflectionMap;
    }

    public double ka() {
        return ka;
    }

    public double kd() {
        return kd;
    }

    /** The diffuse colour, or null when a texture replaced it. */
    public RGBColor cd() {
        return cd;
    }

    public GlossySpecular specular() {
        return specular;
    }

    public PerfectSpecular mirror() {
        return mirror;
    }

    /** Whether the reflected fraction follows Schlick's approximation (kr at normal incidence). */
    public boolean schlick() {
        return schlick;
    }
}

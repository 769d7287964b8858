package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.brdf.PerfectSpecular;
import raytracer.core.Background;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingPass;
import raytracer.core.Texture;
import raytracer.core.WorkerScratch;
import raytracer.math.Fresnel;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Rgb;

/**
 * Phong shading plus a perfect mirror term (Suffern, section 24.3): the radiance traced along the
 * mirror direction, scaled by kr cr, is added to the direct light. With {@code schlick} the
 * reflected fraction grows towards grazing angles by Schlick's Fresnel approximation with kr as
 * the reflectance at normal incidence (report section 3: the brown mirror sphere with 0.5).
 */
public final class Reflective extends Material {
    /** Seen by rays reflected or refracted off this object that escape, instead of the scene's background. */
    private Background reflectionMap;
    /** The environment of the magenta-reflection pass (report figures 4c and 6c). */
    static final Background MAGENTA = (ray, out) -> out.set(1, 0, 1);
    private Lambertian ambient;
    private Lambertian diffuse;
    private final double ka;
    private final double kd;
    private final GlossySpecular specular;
    private final PerfectSpecular mirror;
    private final RGBColor reflectance;
    private final double kr;
    private final boolean schlick;

    public Reflective(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp,
                      double kr, RGBColor cr, boolean schlick) {
        this.kr = kr;
        this.schlick = schlick;
        this.ka = ka;
        this.kd = kd;
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
        this.specular = new GlossySpecular(ks, cs, exp, false);
        this.mirror = new PerfectSpecular(kr, cr);
        this.reflectance = schlick ? cr : mirror.reflectance();
    }

    /** Replaces the diffuse colour by a texture looked up at each hit. */
    public void setTexture(Texture texture) {
        this.ambient = new Lambertian(ka, texture);
        this.diffuse = new Lambertian(kd, texture);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, specular, out);
        int next = sr.depth + 1;
        ShadingPass pass = sr.world.pass();
        if (next > sr.world.viewPlane().maxDepth() || !pass.reflection(sr.depth)) {
            return;
        }
        WorkerScratch scratch = sr.scratch;
        mirror.sampleDirection(sr, sr.wo, sr.wi);
        double fraction = schlick && pass.angleDependent() ? Fresnel.schlick(kr, sr.normal.dot(sr.wo)) : schlick ? kr : 1;
        if (!scratch.branch(sr.depth, reflectance.r() * fraction, reflectance.g() * fraction, reflectance.b() * fraction)) {
            return;
        }
        Ray reflected = sr.spawnRay(sr.wi.x, sr.wi.y, sr.wi.z, scratch.ray(next));
        scratch.secondaryRays++;
        scratch.setEnvironment(next, pass.magentaReflection(sr.depth) ? MAGENTA : reflectionMap);
        Rgb incoming = scratch.color(next);
        sr.world.tracer().traceRay(reflected, next, scratch, incoming);
        out.addProduct(incoming, reflectance, fraction);
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

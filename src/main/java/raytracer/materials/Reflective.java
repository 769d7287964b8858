package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.brdf.PerfectSpecular;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
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
    private final Lambertian ambient;
    private final Lambertian diffuse;
    private final GlossySpecular specular;
    private final PerfectSpecular mirror;
    private final RGBColor reflectance;
    private final double kr;
    private final boolean schlick;

    public Reflective(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp,
                      double kr, RGBColor cr, boolean schlick) {
        this.kr = kr;
        this.schlick = schlick;
        this.ambient = new Lambertian(ka, cd);
        this.diffuse = new Lambertian(kd, cd);
        this.specular = new GlossySpecular(ks, cs, exp, false);
        this.mirror = new PerfectSpecular(kr, cr);
        this.reflectance = schlick ? cr : mirror.reflectance();
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        DirectLighting.shade(sr, ambient, diffuse, specular, out);
        int next = sr.depth + 1;
        if (next > sr.world.viewPlane().maxDepth()) {
            return;
        }
        WorkerScratch scratch = sr.scratch;
        mirror.sampleDirection(sr, sr.wo, sr.wi);
        Ray reflected = sr.spawnRay(sr.wi.x, sr.wi.y, sr.wi.z, scratch.ray(next));
        scratch.secondaryRays++;
        Rgb incoming = scratch.color(next);
        sr.world.tracer().traceRay(reflected, next, scratch, incoming);
        double fraction = schlick ? Fresnel.schlick(kr, sr.normal.dot(sr.wo)) : 1;
        out.addProduct(incoming, reflectance, fraction);
    }

    @Override
    public boolean tracesSecondaryRays() {
        return true;
    }
}

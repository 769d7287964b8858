package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.Lambertian;
import raytracer.brdf.PerfectSpecular;
import raytracer.btdf.PerfectTransmitter;
import raytracer.core.Background;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingPass;
import raytracer.core.WorkerScratch;
import raytracer.math.Fresnel;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/**
 * Glass (report section 3; Suffern, chapter 28): the exact Fresnel reflectance R splits the light
 * into a mirror ray weighted R and a refracted ray weighted 1 - R (R = 1 past the critical angle),
 * plus Phong highlights from the lights. Beer's law: a hit seen from inside the medium ends a
 * segment travelled through it, so the radiance found there is multiplied by exp(-sigma_a t), per
 * channel. That covers refracted rays, internal reflections and camera rays starting inside alike.
 *
 * <p>Radiance is not scaled by (eta_t / eta_i)^2 when crossing: a camera path that enters the
 * medium also leaves it, where the factors cancel, and leaving them out keeps paths cut short by
 * the recursion limit from looking brighter than they are.
 */
public final class Dielectric extends Material {
    /** Seen by rays reflected or refracted off this object that escape, instead of the scene's background. */
    private Background reflectionMap;
    private final Lambertian ambient;
    private final Lambertian diffuse;
    private final GlossySpecular specular;
    private final PerfectSpecular mirror = new PerfectSpecular(1, RGBColor.WHITE);
    private final PerfectTransmitter transmitter;
    private final RGBColor absorption;

    public Dielectric(double ior, RGBColor absorption, double ks, double exp) {
        this.transmitter = new PerfectTransmitter(ior);
        this.absorption = absorption;
        this.ambient = new Lambertian(0, RGBColor.BLACK);
        this.diffuse = new Lambertian(0, RGBColor.BLACK);
        this.specular = new GlossySpecular(ks, RGBColor.WHITE, exp, false);
    }

    @Override
    public void shade(ShadeRec sr, Rgb out) {
        WorkerScratch scratch = sr.scratch;
        // Beer's law: a hit seen from inside ends a segment of length t through the medium
        boolean inside = !sr.frontFace;
        double tr = inside ? Math.exp(-absorption.r() * sr.t) : 1;
        double tg = inside ? Math.exp(-absorption.g() * sr.t) : 1;
        double tb = inside ? Math.exp(-absorption.b() * sr.t) : 1;
        if (inside && sr.object.castsShadows()) {
            // Seen from inside, a light outside the body is reached only through the body's own
            // surface, which casts shadows: every shadow ray would be blocked, so none is traced.
            // (Glass has no diffuse or ambient term, so nothing else is lost.)
            sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
            out.setBlack();
        } else {
            DirectLighting.shade(sr, ambient, diffuse, specular, out);
        }
        int next = sr.depth + 1;
        ShadingPass pass = sr.world.pass();
        if (next <= sr.world.viewPlane().maxDepth()) {
            double cosI = sr.normal.dot(sr.wo);
            double eta = transmitter.relativeEta(sr);
            Vec3 wi = sr.wi;
            boolean refracts = transmitter.sampleDirection(sr, sr.wo, wi);
            // the ablation without angle dependence: all refracted, nothing reflected (but for TIR)
            double r = !refracts ? 1 : pass.angleDependent() ? Fresnel.dielectric(cosI, 1, 1 / eta) : 0;
            Rgb incoming = scratch.color(next);
            // the refracted part, 1 - R (wi holds its direction); the branch's weight includes the
            // transmittance of the segment that ended here
            double t = 1 - r;
            if (r < 1 && pass.refraction(sr.depth) && scratch.branch(sr.depth, t * tr, t * tg, t * tb)) {
                trace(sr, wi, next, scratch, incoming, null);
                out.addProduct(incoming, RGBColor.WHITE, t);
            }
            // the mirror part, R (all of it under total internal reflection)
            if (r > 0 && pass.reflection(sr.depth) && scratch.branch(sr.depth, r * tr, r * tg, r * tb)) {
                mirror.sampleDirection(sr, sr.wo, wi);
                trace(sr, wi, next, scratch, incoming, pass.magentaReflection(sr.depth) ? Reflective.MAGENTA : reflectionMap);
                out.addProduct(incoming, RGBColor.WHITE, r);
            }
        }
        if (inside) {
            out.r *= tr;
            out.g *= tg;
            out.b *= tb;
        }
    }

    private void trace(ShadeRec sr, Vec3 direction, int depth, WorkerScratch scratch, Rgb out, Background environment) {
        Ray ray = sr.spawnRay(direction.x, direction.y, direction.z, scratch.ray(depth));
        scratch.secondaryRays++;
        scratch.setEnvironment(depth, environment != null ? environment : reflectionMap);
        sr.world.tracer().traceRay(ray, depth, scratch, out);
    }

    /** Gives this object its own environment for its reflections (report section 1); null: the scene's. */
    public void setReflectionMap(Background reflectionMap) {
        this.reflectionMap = reflectionMap;
    }

    /** The index of refraction inside the surface (outside is vacuum). */
    public double ior() {
        return transmitter.ior();
    }

    @Override
    public boolean tracesSecondaryRays() {
        return true;
    }
}

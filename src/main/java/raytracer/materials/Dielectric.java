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
        DirectLighting.shade(sr, ambient, diffuse, specular, out);
        int next = sr.depth + 1;
        ShadingPass pass = sr.world.pass();
        if (next <= sr.world.viewPlane().maxDepth()) {
            WorkerScratch scratch = sr.scratch;
            double cosI = sr.normal.dot(sr.wo);
            double eta = transmitter.relativeEta(sr);
            Vec3 wi = sr.wi;
            boolean refracts = transmitter.sampleDirection(sr, sr.wo, wi);
            // the ablation without angle dependence: all refracted, nothing reflected (but for TIR)
            double r = !refracts ? 1 : pass.angleDependent() ? Fresnel.dielectric(cosI, 1, 1 / eta) : 0;
            Rgb incoming = scratch.color(next);
            // the refracted part, 1 - R (wi holds its direction)
            if (r < 1 && pass.refraction(sr.depth)) {
                trace(sr, wi, next, scratch, incoming, null);
                out.addProduct(incoming, RGBColor.WHITE, 1 - r);
            }
            // the mirror part, R (all of it under total internal reflection)
            if (r > 0 && pass.reflection(sr.depth)) {
                mirror.sampleDirection(sr, sr.wo, wi);
                trace(sr, wi, next, scratch, incoming, pass.magentaReflection(sr.depth) ? Reflective.MAGENTA : reflectionMap);
                out.addProduct(incoming, RGBColor.WHITE, r);
            }
        }
        if (!sr.frontFace) {
            double t = sr.t;
            out.r *= Math.exp(-absorption.r() * t);
            out.g *= Math.exp(-absorption.g() * t);
            out.b *= Math.exp(-absorption.b() * t);
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

    @Override
    public boolean tracesSecondaryRays() {
        return true;
    }
}

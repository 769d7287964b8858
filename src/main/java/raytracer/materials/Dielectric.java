package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.PerfectSpecular;
import raytracer.btdf.PerfectTransmitter;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingNeeds;
import raytracer.core.WorkerScratch;
import raytracer.math.Fresnel;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * Glass (report section 3; Suffern, chapter 28; area lights: chapter 18): the exact Fresnel
 * reflectance R splits the light into a mirror ray weighted R and a refracted ray weighted 1 - R
 * (R = 1 past the critical angle; the transmitter's sample_f gives that ray and weight), plus
 * Phong highlights from the lights (it extends Phong, as in the book, with no diffuse or ambient term). Beer's law: a hit seen from inside the medium ends a
 * segment travelled through it, so the radiance found there is multiplied by exp(-sigma_a t), per
 * channel. That covers refracted rays, internal reflections and camera rays starting inside alike.
 * A back face means the ray crossed the surface from inside: a ray that only touches the surface
 * does not hit it (ShadeRec.complete), so no ray from outside is charged for a path it never took.
 *
 * <p>Radiance is not scaled by (eta_t / eta_i)^2 when crossing: a camera path that enters the
 * medium also leaves it, where the factors cancel, and leaving them out keeps paths cut short by
 * the recursion limit from looking brighter than they are.
 */
public final class Dielectric extends Phong {
    private final PerfectSpecular mirror = new PerfectSpecular(1, RGBColor.WHITE);
    private final PerfectTransmitter transmitter;
    private final RGBColor absorption;

    public Dielectric(double ior, RGBColor absorption, double ks, double exp) {
        super(0, 0, RGBColor.BLACK, new GlossySpecular(ks, RGBColor.WHITE, exp, false), null);
        this.transmitter = new PerfectTransmitter(ior);
        this.absorption = absorption;
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb out) {
        shadeGlass(sr, out, false);
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb out) {
        shadeGlass(sr, out, true);
    }

    /** Phong's shading, by area_light_shade or not, but with no direct light on a hit seen from inside. */
    private void shadeGlass(ShadeRec sr, MutableRgb out, boolean areaLights) {
        if (seenFromInside(sr, out)) {
            traceRays(sr, out);
            return;
        }
        if (areaLights) {
            super.areaLightShade(sr, out);
        } else {
            super.shade(sr, out);
        }
    }

    /**
     * Seen from inside, a light outside the body is reached only through the body's own surface,
     * which casts shadows: every shadow ray would be blocked, so none is traced and the direct
     * light is black (glass has no diffuse or ambient term, so nothing else is lost). Sets sr.wo.
     */
    private static boolean seenFromInside(ShadeRec sr, MutableRgb out) {
        if (sr.frontFace || !sr.object.castsShadows()) {
            return false;
        }
        sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
        out.setBlack();
        return true;
    }

    /**
     * Adds the refracted ray's radiance weighted 1 - R and the mirror ray's weighted R (Suffern,
     * chapter 28), then applies Beer's law to the whole when the hit ends a segment inside.
     */
    @Override
    void traceRays(ShadeRec sr, MutableRgb out) {
        WorkerScratch scratch = sr.scratch;
        RayTreePolicy policy = scratch.policy;
        // Beer's law: a hit seen from inside ends a segment of length t through the medium
        boolean inside = !sr.frontFace;
        double tr = inside ? Math.exp(-absorption.r() * sr.t) : 1;
        double tg = inside ? Math.exp(-absorption.g() * sr.t) : 1;
        double tb = inside ? Math.exp(-absorption.b() * sr.t) : 1;
        int next = sr.depth + 1;
        if (next <= sr.world.viewPlane().maxDepth()) {
            double cosI = sr.normal.dot(sr.wo);
            double eta = transmitter.relativeEta(sr);
            MutableVec3 wi = sr.wi;
            MutableRgb weight = scratch.weight(sr.depth);
            boolean refracts = transmitter.sampleF(sr, sr.wo, wi, weight);
            // the ablation without angle dependence: all refracted, nothing reflected (but for TIR)
            double r = !refracts ? 1 : policy.angleDependent() ? Fresnel.dielectric(cosI, 1, 1 / eta) : 0;
            double t = !refracts ? 0 : policy.angleDependent() ? weight.r : 1; // = 1 - r
            MutableRgb incoming = scratch.color(next);
            // the refracted part (wi holds its direction); the branch's weight includes the
            // transmittance of the segment that ended here
            if (r < 1 && policy.showsRefraction(sr.depth) && policy.recordBranchWeight(sr.depth, t * tr, t * tg, t * tb)) {
                BranchRay.trace(sr, wi, PixelSamples.REFRACTED, scratch, incoming, reflectionMap());
                out.addProduct(incoming, RGBColor.WHITE, t);
            }
            // the mirror part, R (all of it under total internal reflection)
            if (r > 0 && policy.showsReflection(sr.depth) && policy.recordBranchWeight(sr.depth, r * tr, r * tg, r * tb)) {
                mirror.sampleF(sr, sr.wo, 0, 0, wi, weight);
                BranchRay.trace(sr, wi, PixelSamples.REFLECTED, scratch, incoming, policy.reflectedEnvironment(sr.depth, reflectionMap()));
                out.addProduct(incoming, weight, r);
            }
        }
        if (inside) {
            out.r *= tr;
            out.g *= tg;
            out.b *= tb;
        }
    }

    /** Glass traces reflected and refracted rays: what lies behind it can be seen. */
    @Override
    public ShadingNeeds needs() {
        return new ShadingNeeds(false, true, true, false);
    }

    /** The index of refraction inside the surface (outside is vacuum). */
    public double ior() {
        return transmitter.ior();
    }
}

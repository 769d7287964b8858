package raytracer.materials;

import raytracer.brdf.GlossySpecular;
import raytracer.brdf.PerfectSpecular;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingNeeds;
import raytracer.core.WorkerScratch;
import raytracer.math.Fresnel;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.RGBColor;

/**
 * A thin sheet of glass (a window pane, a glass quad): a slab of index {@code ior} too thin to
 * see into. A single surface has no inside for {@link Dielectric} to take, so from behind it
 * would be the inside of a medium; a sheet is the same from either side. The light crossing it is
 * neither bent nor moved sideways (its two faces are parallel and close), and nothing is absorbed
 * on the way: the transmitted ray goes on in the direction it came. Each face reflects the Fresnel
 * fraction R and passes T = 1 - R (the same from inside: Fresnel's reflectance is reciprocal), and
 * the light bouncing between the faces adds up to
 *
 * <pre>
 *   R' = R + T R T + T R^3 T + ... = R + T^2 R / (1 - R^2) = 2 R / (1 + R),   T' = 1 - R'
 * </pre>
 *
 * as pbrt-v4's ThinDielectricBxDF sums it (src/pbrt/bxdfs.h), from the unpolarised R. Summing
 * each polarisation on its own would be exact for an incoherent slab; the two agree at normal
 * incidence and part towards Brewster's angle (60 degrees, index 1.5: 0.164 against 0.152).
 * Plus Phong highlights from the lights, on either side.
 */
public final class ThinDielectric extends Phong {
    private final PerfectSpecular mirror = new PerfectSpecular(1, RGBColor.WHITE);
    private final double ior;

    public ThinDielectric(double ior, double ks, double exp) {
        super(0, 0, RGBColor.BLACK, new GlossySpecular(ks, RGBColor.WHITE, exp, false), null);
        if (!(ior > 0) || !Double.isFinite(ior)) {
            throw new IllegalArgumentException("index of refraction must be positive, got " + ior);
        }
        this.ior = ior;
    }

    /**
     * The sheet's reflectance R' for light arriving at cos(theta_i) = {@code cosI} on a slab of
     * index {@code ior} in vacuum; it transmits the rest. 1 at grazing incidence, where R = 1.
     */
    static double reflectance(double cosI, double ior) {
        double r = Fresnel.dielectric(cosI, 1, ior);
        return r < 1 ? r + (1 - r) * (1 - r) * r / (1 - r * r) : 1;
    }

    /**
     * Adds the radiance found straight on through the sheet weighted T' and the mirror ray's
     * weighted R' (the lighting has set sr.wo). No Beer's law: the sheet has no thickness to
     * absorb over.
     */
    @Override
    void traceRays(ShadeRec sr, MutableRgb out) {
        int next = sr.depth + 1;
        if (next > sr.world.viewPlane().maxDepth()) {
            return;
        }
        WorkerScratch scratch = sr.scratch;
        RayTreePolicy policy = scratch.policy;
        // the ablation without angle dependence: all transmitted, nothing reflected (as Dielectric)
        double r = policy.angleDependent() ? reflectance(sr.normal.dot(sr.wo), ior) : 0;
        double t = 1 - r;
        MutableVec3 wi = sr.wi;
        MutableRgb incoming = scratch.color(next);
        if (t > 0 && policy.showsRefraction(sr.depth) && policy.recordBranchWeight(sr.depth, t, t, t)) {
            wi.set(sr.ray.dx, sr.ray.dy, sr.ray.dz);
            BranchRay.trace(sr, wi, PixelSamples.REFRACTED, scratch, incoming, reflectionMap());
            out.addProduct(incoming, RGBColor.WHITE, t);
        }
        if (r > 0 && policy.showsReflection(sr.depth) && policy.recordBranchWeight(sr.depth, r, r, r)) {
            MutableRgb weight = scratch.weight(sr.depth);
            mirror.sampleF(sr, sr.wo, 0, 0, wi, weight);
            BranchRay.trace(sr, wi, PixelSamples.REFLECTED, scratch, incoming, policy.reflectedEnvironment(sr.depth, reflectionMap()));
            out.addProduct(incoming, weight, r);
        }
    }

    /** The transmitted rays go through the surface, as refracted rays do: lights and objects behind it are seen. */
    @Override
    public ShadingNeeds needs() {
        return new ShadingNeeds(false, true, true, false);
    }

    /** The index of refraction of the sheet's glass. */
    public double ior() {
        return ior;
    }
}
